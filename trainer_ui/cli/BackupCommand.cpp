/// \file
/// `colonosim backup --out FILE --as ADMIN`: an online, consistent copy of the
/// records through SQLite's backup API, while other sessions keep writing.

#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <iostream>

namespace colonosim::cli {

int runBackup(std::span<char* const> args)
{
    std::vector<std::string> options = {"--out"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help"}, options);
    if (line.has("--help")) {
        std::cout << "usage: colonosim backup --out FILE --as ADMIN [--db FILE]\n"
                     "Online backup of the records (SQLite backup API); administrators only.\n";
        return 0;
    }
    const auto out = line.value("--out");
    if (!out) {
        throw UsageError("--out FILE is required");
    }
    if (std::filesystem::exists(*out)) {
        throw UsageError("--out = " + *out + " exists already; a backup never overwrites a file");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(""));
    try {
        open.records->backup(actor, *out);
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    }
    std::cout << "backup written: " << *out << " (" << std::filesystem::file_size(*out) << " bytes)\n";
    return 0;
}

}  // namespace colonosim::cli
