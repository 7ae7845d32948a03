// Contact stability report: a scripted operator on several patients, for
// several values of contact.loadRelaxation and of contact.couplingSweeps,
// and how often its tip moved faster than 2 m/s (a step longer than 2 mm) or
// lay more than a scope diameter into the wall, the steps whose chain solve
// the scope's step guard refused, and what the contact solve cost: the
// wall-clock time per loop step, the nodes in the solve, the share of the
// steps whose last solve stopped at the sweep cap and the load change it
// left (contact.sweepTolerance is 0.1 mN), and what the patient felt: the
// peak handle force, the peak contact load on the wall, the peak mesentery
// strain and the steps recorded as perforating. The figures behind the
// parameters' defaults, and behind scope.maxNodeStep's (--max-node-step 1
// leaves the guard out).
//
//   contact_stability [--seconds S] [--seeds 0,1,2,3] [--relaxation 1,0.5,0.3] [--max-node-step M]
//                     [--sweeps 30] [--operator expert|novice] [--prefix-sweeps 0|1]
//                     [--element-points 0,1] [--side-normals 0,1] [--pleat-search 0,1]
//                     [--sticking-friction 0|1] [--pass-tolerance N] [--acceleration 0..10]
//
// Seed 0 is the default colon; any other seed is a generated patient.

#include "bench/ListArgument.h"
#include "bench/PatientFromSeed.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
    long fastSteps = 0;         ///< steps with the tip moving more than kFastStep
    long outside = 0;           ///< steps with the tip more than a scope diameter into the wall
    double deepest = 0;         ///< m
    double furthest = 0;        ///< m along the colon
    long guarded = 0;           ///< steps with a chain solve refused by the scope's step guard
    long steps = 0;             ///< loop steps run
    double seconds = 0;         ///< wall-clock time of the loop steps, s
    double nodes = 0;           ///< nodes in the contact solve, summed over the steps
    long capped = 0;            ///< steps whose last contact solve stopped at the sweep cap
    double cappedResidual = 0;  ///< the load change those solves left, summed, N
    double handleForce = 0;     ///< largest |handle force|, N
    double wallForce = 0;       ///< largest contact load on the wall, N
    double mesentery = 0;       ///< largest mesentery strain
    long perforating = 0;       ///< steps recorded as perforating
};

/// `options`: the contact's parameters under study (a generated patient's
/// case sets none of them: its contact is the defaults').
Outcome runOperator(std::uint64_t seed, const procedure::OperatorStyle& style,
                    const contact::ContactParameters& options, double maxNodeStep, double seconds)
{
    const bench::Patient patient = bench::patientFromSeed(seed);
    procedure::ProcedureSettings settings = patient.settings;
    settings.contact = options;
    settings.scope.maxNodeStep = maxNodeStep;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(patient.anatomy);
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator hands(style);
    Outcome outcome;
    Eigen::Vector3d previous = loop.scope().tipPose().position;
    const auto steps = static_cast<long>(seconds / settings.stepping.loopStep);
    const int cap = static_cast<int>(std::lround(options.couplingSweeps));
    for (long s = 0; s < steps && !hands.finished(); ++s) {
        const procedure::InputSample input = hands.next(loop);
        const auto start = std::chrono::steady_clock::now();
        loop.step(input);
        outcome.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++outcome.steps;
        const Eigen::Vector3d tip = loop.scope().tipPose().position;
        const double depth = loop.lumen().contacts().back().depth;
        outcome.fastSteps += (tip - previous).norm() > kFastStep ? 1 : 0;
        outcome.outside += depth > settings.scope.outerDiameter ? 1 : 0;
        outcome.deepest = std::max(outcome.deepest, depth);
        outcome.furthest = std::max(outcome.furthest, loop.lastFrame().tipArcLength);
        outcome.guarded += loop.scope().guardRetries() > 0 ? 1 : 0;
        outcome.nodes += static_cast<double>(loop.coupling().activeNodes().size());
        if (loop.coupling().sweeps() >= cap &&
            loop.coupling().residual() >= settings.contact.sweepTolerance) {
            ++outcome.capped;
            outcome.cappedResidual += loop.coupling().residual();
        }
        const procedure::ProcedureFrame& frame = loop.lastFrame();
        outcome.handleForce = std::max(outcome.handleForce, std::abs(frame.handleForce));
        outcome.wallForce = std::max(outcome.wallForce, frame.maxWallForce);
        outcome.mesentery = std::max(outcome.mesentery, frame.mesenteryStrain);
        outcome.perforating += frame.perforation ? 1 : 0;
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
    std::vector<double> sweepCaps{contact::ContactParameters{}.couplingSweeps};
    bool novice = false;
    // The single-valued options; the lists below are swept.
    contact::ContactParameters options;
    std::vector<double> elementPoints{contact::ContactParameters{}.elementPoints};
    std::vector<double> sideNormals{contact::ContactParameters{}.sideNormals};
    std::vector<double> pleatSearch{contact::ContactParameters{}.pleatSearch};
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
            } else if (flag == "--sweeps") {
                const auto& spec = contact::ContactParameters::sweepsSpec;
                sweepCaps = bench::parseList(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--prefix-sweeps") {
                const auto& spec = contact::ContactParameters::prefixSweepsSpec;
                options.prefixSweeps = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--sticking-friction") {
                const auto& spec = contact::ContactParameters::stickingFrictionSpec;
                options.stickingFriction =
                    bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--pass-tolerance") {
                const auto& spec = contact::ContactParameters::passToleranceSpec;
                options.passSweepTolerance = bench::parseNumber(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--acceleration") {
                const auto& spec = contact::ContactParameters::accelerationSpec;
                options.sweepAcceleration = bench::parseNumber(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--element-points") {
                const auto& spec = contact::ContactParameters::elementPointsSpec;
                elementPoints = bench::parseList(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--side-normals") {
                const auto& spec = contact::ContactParameters::sideNormalsSpec;
                sideNormals = bench::parseList(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--pleat-search") {
                const auto& spec = contact::ContactParameters::pleatSearchSpec;
                pleatSearch = bench::parseList(flag, value, spec.minValue, spec.maxValue);
            } else if (flag == "--operator") {
                if (value != "expert" && value != "novice") {
                    throw std::invalid_argument("--operator = '" + value + "' is not one of expert, novice");
                }
                novice = value == "novice";
            } else {
                throw std::invalid_argument(
                    "unknown option '" + flag +
                    "' (allowed: --seconds, --seeds, --relaxation, --max-node-step, --sweeps, --operator, "
                    "--prefix-sweeps, --element-points, --side-normals, --pleat-search, "
                    "--sticking-friction, --pass-tolerance, --acceleration)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "contact_stability: %s\n", error.what());
        return 2;
    }
    std::printf(
        "%s, %.1f s per run, scope.maxNodeStep %.4g m, contact.prefixSweeps %.0f, contact.stickingFriction "
        "%.0f, contact.passSweepTolerance %.3g N, contact.sweepAcceleration %.0f; fast: tip steps longer "
        "than 2 mm; outside: "
        "steps with the tip more than a scope diameter into the wall; guarded: steps with a chain solve "
        "refused by the step guard; us/step: wall-clock time of a loop step; nodes: mean nodes in the "
        "contact solve; capped: steps whose last solve stopped at the sweep cap with loads still changing, "
        "and the mean change left (mN); points: contact.elementPoints; side: contact.sideNormals; pleat: "
        "contact.pleatSearch; handle_N, "
        "wall_N: peak handle force "
        "and peak contact load on the wall; mesentery: peak strain; perforating: steps recorded so\n",
        novice ? "novice" : "expert", seconds, maxNodeStep, options.prefixSweeps, options.stickingFriction,
        options.passSweepTolerance, options.sweepAcceleration);
    std::printf("%-10s %-6s %-6s %-4s %-5s %-6s %10s %10s %12s %12s %9s %9s %7s %8s %10s %9s %9s %10s %11s\n",
                "relaxation", "sweeps", "points", "side", "pleat", "seed", "fast", "outside", "deepest_mm",
                "furthest_m", "guarded", "us/step", "nodes", "capped", "left_mN", "handle_N", "wall_N",
                "mesentery", "perforating");
    const procedure::OperatorStyle style = novice ? procedure::noviceStyle() : procedure::expertStyle();
    for (const double pleat : pleatSearch) {
        for (const double side : sideNormals) {
            for (const double points : elementPoints) {
                for (const double sweeps : sweepCaps) {
                    for (const double relaxation : relaxations) {
                        Outcome total;
                        options.loadRelaxation = relaxation;
                        options.couplingSweeps = sweeps;
                        options.elementPoints = points;
                        options.sideNormals = side;
                        options.pleatSearch = pleat;
                        for (const std::uint64_t seed : seeds) {
                            const Outcome o = runOperator(seed, style, options, maxNodeStep, seconds);
                            const double steps = static_cast<double>(std::max(o.steps, 1L));
                            std::printf("%-10.2f %-6.0f %-6.0f %-4.0f %-5.0f %-6llu %10ld %10ld %12.1f "
                                        "%12.3f %9ld %9.0f %7.1f "
                                        "%7.1f%% %10.3f "
                                        "%9.1f %9.1f %10.3f %11ld\n",
                                        relaxation, sweeps, points, side, pleat,
                                        static_cast<unsigned long long>(seed), o.fastSteps, o.outside,
                                        o.deepest * 1e3, o.furthest, o.guarded, o.seconds / steps * 1e6,
                                        o.nodes / steps, 100.0 * static_cast<double>(o.capped) / steps,
                                        o.capped > 0 ? o.cappedResidual / static_cast<double>(o.capped) * 1e3
                                                     : 0.0,
                                        o.handleForce, o.wallForce, o.mesentery, o.perforating);
                            std::fflush(stdout);
                            total.fastSteps += o.fastSteps;
                            total.outside += o.outside;
                            total.deepest = std::max(total.deepest, o.deepest);
                        }
                        std::printf("%-10.2f %-6.0f %-6.0f %-4.0f %-5.0f %-6s %10ld %10ld %12.1f\n",
                                    relaxation, sweeps, points, side, pleat, "all", total.fastSteps,
                                    total.outside, total.deepest * 1e3);
                    }
                }
            }
        }
    }
    return 0;
}
