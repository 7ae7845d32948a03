// Contact stability report: the scripted expert on several patients, for
// several values of contact.loadRelaxation, and how often its tip moved
// faster than 2 m/s (a step longer than 2 mm) or lay more than a scope
// diameter into the wall, and the steps whose chain solve the scope's step
// guard refused. The figures behind the parameter's default, and behind
// scope.maxNodeStep's (--max-node-step 1 leaves the guard out).
//
//   contact_stability [--seconds S] [--seeds 0,1,2,3] [--relaxation 1,0.5,0.3] [--max-node-step M]
//
// Seed 0 is the default colon; any other seed is a generated patient.

#include "bench/ListArgument.h"
#include "bench/PatientFromSeed.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace colonosim;

constexpr double kFastStep = 2e-3;  ///< m of tip motion in one 1 ms step: faster than 2 m/s

struct Outcome {
    long fastSteps = 0;   ///< steps with the tip moving more than kFastStep
    long outside = 0;     ///< steps with the tip more than a scope diameter into the wall
    double deepest = 0;   ///< m
    double furthest = 0;  ///< m along the colon
    long guarded = 0;     ///< steps with a chain solve refused by the scope's step guard
};

Outcome runExpert(std::uint64_t seed, double relaxation, double maxNodeStep, double seconds)
{
    const bench::Patient patient = bench::patientFromSeed(seed);
    procedure::ProcedureSettings settings = patient.settings;
    settings.contact.loadRelaxation = relaxation;
    settings.scope.maxNodeStep = maxNodeStep;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(patient.anatomy);
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    Outcome outcome;
    Eigen::Vector3d previous = loop.scope().tipPose().position;
    const auto steps = static_cast<long>(seconds / settings.stepping.loopStep);
    for (long s = 0; s < steps && !expert.finished(); ++s) {
        loop.step(expert.next(loop));
        const Eigen::Vector3d tip = loop.scope().tipPose().position;
        const double depth = loop.lumen().contacts().back().depth;
        outcome.fastSteps += (tip - previous).norm() > kFastStep ? 1 : 0;
        outcome.outside += depth > settings.scope.outerDiameter ? 1 : 0;
        outcome.deepest = std::max(outcome.deepest, depth);
        outcome.furthest = std::max(outcome.furthest, loop.lastFrame().tipArcLength);
        outcome.guarded += loop.scope().guardRetries() > 0 ? 1 : 0;
        previous = tip;
    }
    return outcome;
}

}  // namespace

int main(int argc, char** argv)
{
    double seconds = 50.0;
    std::vector<std::uint64_t> seeds{0, 1, 2, 3};
    std::vector<double> relaxations{1.0, 0.5, 0.3};
    double maxNodeStep = scope::ScopeParameters{}.maxNodeStep;
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            if (flag == "--seconds") {
                seconds = bench::parseList(flag, value, 0.001, 3600.0).front();
            } else if (flag == "--seeds") {
                seeds = bench::parseSeeds(flag, value);
            } else if (flag == "--relaxation") {
                relaxations = bench::parseList(flag, value, 0.05, 1.0);
            } else if (flag == "--max-node-step") {
                const auto& spec = scope::ScopeParameters::maxNodeStepSpec;
                maxNodeStep = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --seconds, --seeds, --relaxation, --max-node-step)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "contact_stability: %s\n", error.what());
        return 2;
    }
    std::printf(
        "expert, %.1f s per run, scope.maxNodeStep %.4g m; fast: tip steps longer than 2 mm; outside: "
        "steps with the tip more than a scope diameter into the wall; guarded: steps with a chain solve "
        "refused by the step guard\n",
        seconds, maxNodeStep);
    std::printf("%-10s %-6s %10s %10s %12s %12s %9s\n", "relaxation", "seed", "fast", "outside", "deepest_mm",
                "furthest_m", "guarded");
    for (const double relaxation : relaxations) {
        Outcome total;
        for (const std::uint64_t seed : seeds) {
            const Outcome o = runExpert(seed, relaxation, maxNodeStep, seconds);
            std::printf("%-10.2f %-6llu %10ld %10ld %12.1f %12.3f %9ld\n", relaxation,
                        static_cast<unsigned long long>(seed), o.fastSteps, o.outside, o.deepest * 1e3,
                        o.furthest, o.guarded);
            std::fflush(stdout);
            total.fastSteps += o.fastSteps;
            total.outside += o.outside;
            total.deepest = std::max(total.deepest, o.deepest);
        }
        std::printf("%-10.2f %-6s %10ld %10ld %12.1f\n", relaxation, "all", total.fastSteps, total.outside,
                    total.deepest * 1e3);
    }
    return 0;
}
