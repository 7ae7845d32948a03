// bench_report [--quick] --out DIR: writes the speed-versus-error report
// (speed_vs_error.csv, speed_vs_error.svg, scope_speed_vs_error.csv,
// summary.json) into DIR.

#include "bench/report/BenchReport.h"

#include <iostream>
#include <string>

int main(int argc, char** argv)
{
    colonosim::bench::BenchReportOptions options;
    bool haveOut = false;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--out" && a + 1 < argc) {
            options.outDir = argv[++a];
            haveOut = true;
        } else {
            std::cerr << "bench_report: unexpected argument '" << arg << "'\n"
                      << "usage: bench_report [--quick] --out DIR\n";
            return 2;
        }
    }
    if (!haveOut || options.outDir.empty()) {
        std::cerr << "bench_report: --out DIR is required\nusage: bench_report [--quick] --out DIR\n";
        return 2;
    }
    return colonosim::bench::runBenchReport(options, std::cout);
}
