// Hooked hard case report: the scenario of
// HardCases.AHookedShaftPushedWithTorqueInARedundantSigmoidTwistedHardStaysStable
// (tests/procedure/ProcedureHardCasesTest.cpp) run with the contact options
// chosen on the command line. The novice inserts into the redundant sigmoid
// for 15 s; the tip is then hooked with the up/down dial at its stop and the
// shaft pushed on at 5 cm/s while turned clockwise at 1 rad/s for 7 s; then,
// the insertion held, the handle is twisted a whole turn counter-clockwise in
// 1 s and back in 1 s. Prints the state every 0.25 s from 14 s on, then per
// phase (insertion, hooked push, twist): the steps with the tip more than a
// scope diameter into the wall, the steps whose tissue step was retried, the
// peak handle force and torque, and the deepest the tip went.
//
//   hooked_case [--element-points 0-3] [--side-normals 0|1] [--pleat-search 0|1]
//               [--max-node-step M]
//
// Each flag's default is the parameter's (contact/ContactParameters.h; the
// scope's step guard scope.maxNodeStep, m, scope/ScopeParameters.h).

#include "bench/ListArgument.h"
#include "simcore/contact/ContactParameters.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/params/Parameter.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/scope/ScopeParameters.h"
#include "tests/procedure/HookedCase.h"
#include "tests/procedure/LoopObservation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

namespace {

using namespace colonosim;

constexpr int kPrintEvery = 250;  ///< steps between printed states

struct Phase {
    const char* name;
    long outside = 0;         ///< steps with the tip more than a scope diameter in
    long retried = 0;         ///< steps whose tissue step was retried
    double peakForce = 0.0;   ///< N
    double peakTorque = 0.0;  ///< N m
    double deepest = 0.0;     ///< m
};

}  // namespace

int main(int argc, char** argv)
{
    procedure::ProcedureSettings settings;
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            const auto parse = [&](const params::ParameterSpec& spec) {
                return bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            };
            if (flag == "--element-points") {
                settings.contact.elementPoints = parse(contact::ContactParameters::elementPointsSpec);
            } else if (flag == "--side-normals") {
                settings.contact.sideNormals = parse(contact::ContactParameters::sideNormalsSpec);
            } else if (flag == "--pleat-search") {
                settings.contact.pleatSearch = parse(contact::ContactParameters::pleatSearchSpec);
            } else if (flag == "--max-node-step") {
                settings.scope.maxNodeStep = parse(scope::ScopeParameters::maxNodeStepSpec);
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --element-points, --side-normals, --pleat-search, "
                                            "--max-node-step)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "hooked_case: %s\n", error.what());
        return 2;
    }
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(looptest::redundantSigmoid());
    procedure::ProcedureLoop loop(anatomy, settings);
    const double diameter = settings.scope.outerDiameter;
    std::printf("hooked case; contact options: elementPoints %g, sideNormals %g, pleatSearch %g; "
                "scope.maxNodeStep %g m\n",
                settings.contact.elementPoints, settings.contact.sideNormals, settings.contact.pleatSearch,
                settings.scope.maxNodeStep);
    std::printf("%7s %9s %10s %10s %9s %8s %9s  %s\n", "t_s", "force_N", "torque_Nm", "tip_in_mm", "outside",
                "retried", "stored_m", "loop");
    std::array<Phase, 3> phases{Phase{"insertion"}, Phase{"hooked push"}, Phase{"twist"}};
    looptest::HookedCaseDriver driver;
    for (int s = 0; s < looptest::kHookedSteps; ++s) {
        const long triesBefore = loop.tissue().rejectedSteps();
        loop.step(driver.next(loop));
        Phase& phase = phases[driver.phase()];
        const double depth = loop.lumen().contacts().empty() ? 0.0 : loop.lumen().contacts().back().depth;
        phase.outside += depth > diameter ? 1 : 0;
        phase.retried += loop.tissue().rejectedSteps() > triesBefore ? 1 : 0;
        phase.peakForce = std::max(phase.peakForce, std::abs(loop.outputs().handleForce));
        phase.peakTorque = std::max(phase.peakTorque, std::abs(loop.outputs().handleTorque));
        phase.deepest = std::max(phase.deepest, depth);
        if (s >= looptest::kHookedNovice - 1000 && s % kPrintEvery == kPrintEvery - 1) {
            // Running totals over the phases so far.
            long outside = 0;
            long retried = 0;
            for (const Phase& p : phases) {
                outside += p.outside;
                retried += p.retried;
            }
            std::printf("%7.2f %9.1f %10.2f %10.1f %9ld %8ld %9.3f  %s\n", loop.time(),
                        loop.outputs().handleForce, loop.outputs().handleTorque, depth * 1e3, outside,
                        retried, loop.loops().signals().storedShaft,
                        std::string(procedure::loopName(loop.loops().current())).c_str());
        }
    }
    std::printf("%-12s %9s %8s %12s %14s %13s\n", "phase", "outside", "retried", "peak_F_N", "peak_torque_Nm",
                "deepest_mm");
    for (const Phase& phase : phases) {
        std::printf("%-12s %9ld %8ld %12.1f %14.2f %13.1f\n", phase.name, phase.outside, phase.retried,
                    phase.peakForce, phase.peakTorque, phase.deepest * 1e3);
    }
    return 0;
}
