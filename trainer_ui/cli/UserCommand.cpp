/// \file
/// `colonosim user add|list|passwd`: the users of the records. Acting users
/// authenticate with `--as NAME` and COLONOSIM_PASSWORD or --password-file;
/// a new password comes from COLONOSIM_NEW_PASSWORD or --new-password-file.
/// `colonosim user cohort add COHORT | member COHORT USER | instructor COHORT USER`
/// sets up cohorts: an instructor reads the records of the students of the
/// cohorts they are assigned to.

#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace colonosim::cli {

int runUser(std::span<char* const> args)
{
    std::vector<std::string> options = {"--role", "--new-password-file"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help", "--json"}, options);
    const auto& words = line.positional();
    if (line.has("--help") || words.empty()) {
        std::cout << "usage: colonosim user add NAME --role student|instructor|administrator --as ADMIN\n"
                     "       colonosim user list --as NAME [--json]\n"
                     "       colonosim user passwd NAME --as NAME\n"
                     "       colonosim user cohort add COHORT | member COHORT USER | instructor COHORT USER "
                     "--as ADMIN\n"
                     "  --db FILE               the records (default: records.sqlite in the user's data "
                     "directory)\n"
                     "  --as NAME               who acts; password from COLONOSIM_PASSWORD or "
                     "--password-file FILE\n"
                     "  --new-password-file F   the new password (else COLONOSIM_NEW_PASSWORD)\n"
                     "Only administrators add users, manage cohorts or change another user's password.\n";
        return line.has("--help") ? 0 : 2;
    }
    const std::string& action = words[0];
    if (action != "add" && action != "list" && action != "passwd" && action != "cohort") {
        throw UsageError("action = " + action + " is not one of add, list, passwd, cohort");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(""));
    try {
        if (action == "cohort") {
            const std::string what = words.size() > 1 ? words[1] : "";
            if (what == "add" && words.size() == 3) {
                open.records->addCohort(actor, words[2]);
                std::cout << "cohort " << words[2] << " added\n";
            } else if (what == "member" && words.size() == 4) {
                open.records->addMember(actor, words[2], words[3]);
                std::cout << words[3] << " is a member of " << words[2] << '\n';
            } else if (what == "instructor" && words.size() == 4) {
                open.records->assignInstructor(actor, words[2], words[3]);
                std::cout << words[3] << " instructs " << words[2] << '\n';
            } else {
                throw UsageError(
                    "expected: user cohort add COHORT | member COHORT USER | instructor COHORT USER");
            }
            return 0;
        }
        if (action == "list") {
            nlohmann::json out = nlohmann::json::array();
            for (const db::UserRow& u : open.records->listUsers(actor)) {
                out.push_back({{"name", u.name}, {"role", db::roleName(u.role)}, {"created", u.createdAt}});
                if (!line.has("--json")) {
                    std::cout << u.name << '\t' << db::roleName(u.role) << '\t' << u.createdAt << '\n';
                }
            }
            if (line.has("--json")) {
                std::cout << out.dump(2) << '\n';
            }
            return 0;
        }
        if (words.size() != 2) {
            throw UsageError("user " + action + " needs exactly one NAME");
        }
        const std::string password =
            readSecret(line, "--new-password-file", "COLONOSIM_NEW_PASSWORD", "new password of " + words[1]);
        if (action == "add") {
            const auto role = line.value("--role");
            if (!role) {
                throw UsageError("--role is required: student, instructor or administrator");
            }
            db::Role parsed;
            try {
                parsed = db::parseRole(*role);
            } catch (const db::DatabaseError& error) {
                throw UsageError(std::string("--role: ") + error.what());
            }
            open.records->addUser(actor, words[1], parsed, password);
            std::cout << "added " << words[1] << " (" << *role << ")\n";
        } else {
            open.records->setPassword(actor, words[1], password);
            std::cout << "password of " << words[1] << " changed\n";
        }
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    } catch (const db::DatabaseError& error) {
        throw UsageError(error.what());
    }
    return 0;
}

}  // namespace colonosim::cli
