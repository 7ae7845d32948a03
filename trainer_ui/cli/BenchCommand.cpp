/// \file
/// `colonosim bench [--quick] --out DIR`: the speed-versus-error report
/// (bench/report/BenchReport.h): speed_vs_error.csv, speed_vs_error.svg,
/// scope_speed_vs_error.csv and summary.json in DIR.

#include "bench/report/BenchReport.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <iostream>

namespace colonosim::cli {

int runBench(std::span<char* const> args)
{
    const CommandLine line(args, {"--quick", "--help"}, {"--out"});
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim bench [--quick] --out DIR\n"
               "Speed versus error of every integrator on the bench scene, the Bullet btSoftBody peer,\n"
               "the active region's speed-up and error, step and mapping rates, the colonoscope step and\n"
               "the chain solver's speed against error, the procedure loop step rate. Writes\n"
               "DIR/speed_vs_error.csv, DIR/speed_vs_error.svg, DIR/scope_speed_vs_error.csv and\n"
               "DIR/summary.json.\n"
               "  --quick   short runs (about a minute) for smoke tests\n";
        return 0;
    }
    if (!line.positional().empty()) {
        throw UsageError("bench takes no arguments, got " + line.positional().front());
    }
    const std::optional<std::string> out = line.value("--out");
    if (!out || out->empty()) {
        throw UsageError("--out DIR is required");
    }
    bench::BenchReportOptions options;
    options.quick = line.has("--quick");
    options.outDir = *out;
    return bench::runBenchReport(options, std::cout);
}

}  // namespace colonosim::cli
