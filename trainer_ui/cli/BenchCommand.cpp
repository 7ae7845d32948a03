/// \file
/// `colonosim bench [--quick] --out DIR`: the speed-versus-error report.

#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <iostream>

namespace colonosim::cli {

int runBench(std::span<char* const> args)
{
    const CommandLine line(args, {"--quick", "--help"}, {"--out"});
    if (line.has("--help")) {
        std::cout << "usage: colonosim bench [--quick] --out DIR\n";
        return 0;
    }
    throw UsageError("the bench report is not built into this binary yet");
}

}  // namespace colonosim::cli
