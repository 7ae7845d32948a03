/// \file
/// `colonosim progress --user NAME [--as NAME] [--json]`: a trainee's standing
/// in the core curriculum (task states under proficiency-based progression),
/// their CUSUM and LC-CUSUM learning curve of cecal intubation, and the
/// certification rules met and not met. A student sees only themselves, an
/// instructor the students of their cohorts, an administrator everyone.

#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/reports/ProgressReport.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

namespace colonosim::cli {

int runProgress(std::span<char* const> args)
{
    std::vector<std::string> options = {"--user"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help", "--json"}, options);
    if (line.has("--help")) {
        std::cout << "usage: colonosim progress --user NAME [--as NAME] [--db FILE] [--json]\n"
                     "Task states (two consecutive met benchmarks make a task proficient and unlock what\n"
                     "follows), the CUSUM / LC-CUSUM learning curve of cecal intubation, and the\n"
                     "certification rules. --as defaults to --user; password from COLONOSIM_PASSWORD or\n"
                     "--password-file FILE.\n";
        return 0;
    }
    const auto user = line.value("--user");
    if (!user) {
        throw UsageError("--user NAME is required");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(*user));
    nlohmann::json report;
    try {
        report = reports::progressReport(*open.database, *open.records, actor, *user);
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    } catch (const db::DatabaseError& error) {
        throw UsageError(error.what());
    }
    if (line.has("--json")) {
        std::cout << report.dump(2) << '\n';
        return 0;
    }
    std::cout << *user << ": " << report["completed_sessions"] << " completed session(s)\n\ntasks:\n";
    for (const auto& t : report["tasks"]) {
        std::cout << "  " << t["state"].get<std::string>() << "\t" << t["id"].get<std::string>()
                  << (t.contains("why") ? "  (" + t["why"].get<std::string>() + ")" : std::string()) << '\n';
    }
    const auto& lc = report["learning_curve"];
    std::cout << "\nlearning curve (cecal intubation; acceptable " << lc["acceptable_failure_rate"]
              << ", unacceptable " << lc["unacceptable_failure_rate"] << "): ";
    if (lc["cusum"].empty()) {
        std::cout << "no sessions yet\n";
    } else {
        std::cout << "CUSUM " << lc["cusum"].back() << " (h1 " << lc["cusum_h1"] << "), LC-CUSUM "
                  << lc["lc_cusum"].back() << " (h " << lc["lc_cusum_h"] << ")"
                  << (lc["competent_at"].get<int>() > 0
                          ? ", competent at procedure " + std::to_string(lc["competent_at"].get<int>())
                          : std::string(", competence not yet signalled"))
                  << '\n';
    }
    std::cout << "\ncertification (rule set " << reports::ruleSetLabel(report) << "):\n";
    for (const auto& r : report["certification"]) {
        std::cout << "  " << (r["met"].get<bool>() ? "met    " : "not met") << "  "
                  << r["description"].get<std::string>() << " (observed "
                  << reports::observedText(r["observed"].is_null() ? std::nan("")
                                                                   : r["observed"].get<double>())
                  << " over " << reports::sessionsText(r) << " session(s))\n";
    }
    return 0;
}

}  // namespace colonosim::cli
