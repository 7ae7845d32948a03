#include "trainer_ui/cli/CaseArgument.h"

#include "case_generator/CaseReader.h"
#include "trainer_ui/cli/CommandLine.h"

namespace colonosim::cli {

cases::Case readCaseArgument(const std::string& path)
{
    cases::ReadResult read = cases::readCaseFile(path);
    if (!read.ok()) {
        std::string message = "--case " + path + " is not a valid case:";
        for (const std::string& error : read.errors) {
            message += "\n  " + error;
        }
        throw UsageError(message);
    }
    return std::move(*read.value);
}

}  // namespace colonosim::cli
