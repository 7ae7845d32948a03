// Paced loop report: the cost of a loop step when the loop waits between
// steps, as it does when a device or the wall clock sets the pace. The
// default colon is pushed in at 2 cm/s from the anus (the HDC's simulated
// hand, `colonosim-hdc --hand push`), one step a millisecond of wall time,
// and between steps the thread either sleeps until the next millisecond or
// polls the clock (as HdcServer::waitForInput() polls for the device's
// frame). Each step's own time is taken; the table gives its quantiles from
// `--from` seconds on (the tip in the sigmoid past about 5 s) and how many
// steps took longer than 0.9 ms, after which a device's answer risks
// coming a servo tick late. The two ways alternate, `--rounds` times each,
// in one process.
//
//   paced_loop [--seconds 12] [--from 5] [--rounds 2]
//
// About 4 x 12 s of wall time at the defaults.

#include "bench/ListArgument.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <thread>
#include <vector>

using namespace colonosim;

namespace {

using Clock = std::chrono::steady_clock;

/// Each step's own time, s, over `seconds` of 1 kHz steps paced by the wall clock.
std::vector<double> pacedRun(const geometry::ColonAnatomy& anatomy, double seconds, bool poll)
{
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    const auto steps = static_cast<long>(seconds * 1000.0 + 0.5);
    std::vector<double> took;
    took.reserve(static_cast<size_t>(steps));
    Clock::time_point next = Clock::now();
    for (long k = 1; k <= steps; ++k) {
        procedure::InputSample in;
        in.insertion = 0.02 * static_cast<double>(k) * 1e-3;  // 2 cm/s
        const Clock::time_point start = Clock::now();
        loop.step(in);
        const Clock::time_point end = Clock::now();
        took.push_back(std::chrono::duration<double>(end - start).count());
        next += std::chrono::microseconds(1000);
        if (end >= next) {
            next = end;  // behind: the next step at once, a fresh schedule
        } else if (poll) {
            while (Clock::now() < next) {
            }
        } else {
            std::this_thread::sleep_until(next);
        }
    }
    return took;
}

void report(const char* way, std::vector<double> took, double from)
{
    took.erase(took.begin(), took.begin() + std::min<long>(static_cast<long>(from * 1000.0),
                                                           static_cast<long>(took.size())));
    std::sort(took.begin(), took.end());
    const auto at = [&took](double q) {
        return 1e6 *
               took[std::min(took.size() - 1, static_cast<size_t>(q * static_cast<double>(took.size())))];
    };
    const auto over = std::count_if(took.begin(), took.end(), [](double t) { return t > 0.9e-3; });
    std::printf("%-6s %8.0f %8.0f %8.0f %8.0f %10ld of %zu\n", way, at(0.5), at(0.9), at(0.99),
                1e6 * took.back(), static_cast<long>(over), took.size());
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv)
{
    double seconds = 12.0;
    double from = 5.0;
    int rounds = 2;
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            if (flag == "--seconds") {
                seconds = bench::parseList(flag, value, 1.0, 60.0).front();
            } else if (flag == "--from") {
                from = bench::parseList(flag, value, 0.0, 59.0).front();
            } else if (flag == "--rounds") {
                rounds = static_cast<int>(bench::parseList(flag, value, 1.0, 20.0).front());
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --seconds, --from, --rounds)");
            }
        });
        if (from >= seconds) {
            throw std::invalid_argument("--from " + bench::shortest(from) + " must be below --seconds " +
                                        bench::shortest(seconds));
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "paced_loop: %s\n", error.what());
        return 2;
    }
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    std::printf("each step's own time (us) from %g s to %g s of the 2 cm/s push, paced at 1 kHz\n", from,
                seconds);
    std::printf("%-6s %8s %8s %8s %8s %10s\n", "wait", "p50", "p90", "p99", "max", "over 0.9 ms");
    for (int r = 0; r < rounds; ++r) {
        report("sleep", pacedRun(anatomy, seconds, false), from);
        report("poll", pacedRun(anatomy, seconds, true), from);
    }
    return 0;
}
