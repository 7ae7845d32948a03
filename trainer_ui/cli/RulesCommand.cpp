/// \file
/// `colonosim rules list|import FILE|activate VERSION --as ADMIN [--db FILE] [--json]`:
/// the certification rule sets of record (db/CertificationRules.h). Import
/// checks the file completely and stores it as a new, inactive version (the
/// file's `version` attribute, above every stored one); activate makes a
/// stored version the one certification status is judged by. Only
/// administrators import or activate; the acting user authenticates with
/// `--as NAME` and COLONOSIM_PASSWORD or --password-file, as `user` does.

#include "db/CertificationRules.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/reports/TraineeReport.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <iostream>

namespace colonosim::cli {

namespace {

nlohmann::json toJson(const db::RuleSetVersion& v)
{
    return {{"name", v.name},
            {"version", v.version},
            {"imported_by", v.importedBy.empty() ? nlohmann::json() : nlohmann::json(v.importedBy)},
            {"imported_at", v.importedAt},
            {"active", v.active}};
}

void print(const db::RuleSetVersion& v)
{
    std::cout << v.version << '\t' << v.name << '\t' << (v.importedBy.empty() ? "(shipped)" : v.importedBy)
              << '\t' << v.importedAt << (v.active ? "\tactive" : "") << '\n';
}

int parseVersion(const std::string& text)
{
    int version = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), version);
    if (error != std::errc() || end != text.data() + text.size() || version < 1) {
        throw UsageError("VERSION = " + text + " is not a whole number of at least 1");
    }
    return version;
}

}  // namespace

int runRules(std::span<char* const> args)
{
    const CommandLine line(args, {"--help", "--json"}, kRecordsOptions);
    const auto& words = line.positional();
    if (line.has("--help") || words.empty()) {
        std::cout << "usage: colonosim rules list --as NAME [--json]\n"
                     "       colonosim rules import FILE --as ADMIN [--json]\n"
                     "       colonosim rules activate VERSION --as ADMIN\n"
                     "  --db FILE   the records (default: records.sqlite in the user's data directory)\n"
                     "  --as NAME   who acts; password from COLONOSIM_PASSWORD or --password-file FILE\n"
                     "The certification rule sets of record: the shipped set is version 1; an import is\n"
                     "checked completely and stored as a new version (the file's version attribute, above\n"
                     "every stored one), not yet active; activate makes a stored version the one\n"
                     "certification status and reports are judged by. Only administrators import or\n"
                     "activate; every import and activation is audited.\n";
        return line.has("--help") ? 0 : 2;
    }
    const std::string& action = words[0];
    const size_t expected = action == "list" ? 1 : 2;
    if (action != "list" && action != "import" && action != "activate") {
        throw UsageError("action = " + action + " is not one of list, import, activate");
    }
    if (words.size() != expected) {
        throw UsageError("rules " + action +
                         (expected == 1 ? " takes no argument" : " needs exactly one argument"));
    }
    std::string xml;
    if (action == "import") {
        std::optional<std::string> bytes = reports::readFileWhole(words[1]);
        if (!bytes) {
            throw UsageError(words[1] + ": cannot be read");
        }
        xml = std::move(*bytes);
    }
    const int version = action == "activate" ? parseVersion(words[1]) : 0;
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(""));
    db::CertificationRules rules(*open.database);
    try {
        if (action == "list") {
            nlohmann::json out = nlohmann::json::array();
            for (const db::RuleSetVersion& v : rules.versions(actor)) {
                out.push_back(toJson(v));
                if (!line.has("--json")) {
                    print(v);
                }
            }
            if (line.has("--json")) {
                std::cout << out.dump(2) << '\n';
            }
        } else if (action == "import") {
            const db::RuleSetVersion stored = rules.import(actor, xml, words[1]);
            if (line.has("--json")) {
                std::cout << toJson(stored).dump(2) << '\n';
            } else {
                std::cout << "imported " << stored.name << " version " << stored.version
                          << " (not active: colonosim rules activate " << stored.version << ")\n";
            }
        } else {
            rules.activate(actor, version);
            const db::ActiveRuleSet active = rules.active(actor);
            std::cout << "active: " << active.stored.name << " version " << active.stored.version << '\n';
        }
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    } catch (const db::RuleSetRejected& error) {
        for (const std::string& e : error.errors()) {
            std::cerr << e << '\n';
        }
        throw UsageError(error.what());
    } catch (const db::DatabaseError& error) {
        throw UsageError(error.what());
    }
    return 0;
}

}  // namespace colonosim::cli
