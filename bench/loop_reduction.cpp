// Loop reduction report: the scripted expert pushed into the crossed loop of
// a redundant sigmoid (66 cm, on a 17 cm root, swept to the left:
// anatomy.sigmoidSweep -1; the haustrated wall, tissue.haustralAxialRatio
// 0.07, and the scope's step guard at 10 mm), as the slow test
// SigmoidLoop.TheExpertBacksOffTheReverseAlphaTurningCounterClockwiseAndItComesUndoneSooner
// drives it. The loop there is left-handed, a reverse alpha: the expert
// reads it and backs off turning counter-clockwise. The report says when
// the crossed loop (alpha or reverse alpha) was read and when it came undone,
// how far the handle was turned meanwhile, the largest handle force and
// torque, and whether the shaft still crossed itself after it. Run once per
// line of options, so that the turn, its direction and the friction's spin
// can be told apart:
//
//   loop_reduction [--seconds S] [--spin-friction 0|1] [--sticking-friction 0|1]
//                  [--turn-rate W] [--sweep K] [--root L]
//
// --turn-rate: rad/s the expert turns the shaft while reducing a loop
// (OperatorStyle::reductionTurnRate, 0.5 by default, the way its type asks
// for; 0 withdraws without turning; negative turns the other way). --sweep:
// anatomy.sigmoidSweep (-1 by default; +1 lays the sigmoid the other way
// round, where the expert formed no crossed loop in 70 s); --root:
// anatomy.sigmoidRootLength, m (0.17 by default).

#include "bench/ListArgument.h"
#include "simcore/contact/ContactParameters.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

using namespace colonosim;

namespace {

struct Options {
    double seconds = 70.0;
    double spinFriction = 0.0;
    double stickingFriction = 0.0;
    double turnRate = procedure::OperatorStyle{}.reductionTurnRate;
    double sweep = -1.0;
    double root = 0.17;  ///< m
};

struct Reduction {
    double loopFrom = -1.0;     ///< s, first step a crossed loop (alpha or reverse alpha) was held
    double loopUntil = -1.0;    ///< s, last step it was held
    double turnedInLoop = 0.0;  ///< rad, the handle's rotation while it was held (+ counter-clockwise)
    std::string kind;           ///< the crossed loop's type as first read
    int crossingsAfter = -1;    ///< own and shared crossings at the first analysis after it
    double peakForce = 0.0;     ///< N, the handle
    double peakTorque = 0.0;    ///< N m, the handle
    double furthest = 0.0;      ///< m, the tip along the colon
    bool finite = true;
};

bool crossed(procedure::LoopKind kind)
{
    return kind == procedure::LoopKind::Alpha || kind == procedure::LoopKind::ReverseAlpha;
}

Reduction run(const Options& o)
{
    geometry::AnatomyParameters anatomy;
    anatomy.sigmoidLength = 0.66;
    anatomy.sigmoidMesenteryHeight = 0.089;
    anatomy.sigmoidRootLength = o.root;
    anatomy.sigmoidSweep = o.sweep;
    const geometry::ColonAnatomy colon = geometry::buildProceduralColon(anatomy);
    procedure::ProcedureSettings settings;
    settings.tissue.haustralAxialRatio = 0.07;
    settings.scope.maxNodeStep = 0.01;
    settings.contact.spinFriction = o.spinFriction;
    settings.contact.stickingFriction = o.stickingFriction;
    procedure::ProcedureLoop loop(colon, settings);
    procedure::OperatorStyle style = procedure::expertStyle();
    style.reductionTurnRate = o.turnRate;
    procedure::ScriptedOperator expert(style);
    Reduction r;
    double rotation = 0.0;
    const auto steps = std::lround(o.seconds / settings.stepping.loopStep);
    for (long s = 0; s < steps && !expert.finished(); ++s) {
        const procedure::InputSample input = expert.next(loop);
        if (crossed(loop.loops().current())) {
            r.turnedInLoop += input.rotation - rotation;
        }
        rotation = input.rotation;
        const procedure::ProcedureOutputs& out = loop.step(input);
        r.finite = r.finite && std::isfinite(out.handleForce) && std::isfinite(out.handleTorque);
        r.peakForce = std::max(r.peakForce, std::abs(out.handleForce));
        r.peakTorque = std::max(r.peakTorque, std::abs(out.handleTorque));
        r.furthest = std::max(r.furthest, loop.lastFrame().tipArcLength);
        if (crossed(loop.loops().current())) {
            if (r.loopFrom < 0.0) {
                r.loopFrom = loop.time();
                r.kind = procedure::loopName(loop.loops().current());
            }
            r.loopUntil = loop.time();
            r.crossingsAfter = -1;
        } else if (r.loopFrom >= 0.0 && r.crossingsAfter < 0) {
            const procedure::LoopSignals& signals = loop.loops().signals();
            r.crossingsAfter = signals.crossings + signals.sharedCrossings;
        }
    }
    return r;
}

}  // namespace

int main(int argc, char** argv)
{
    Options o;
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            if (flag == "--seconds") {
                o.seconds = bench::parseList(flag, value, 0.001, 3600.0).front();
            } else if (flag == "--spin-friction") {
                const auto& spec = contact::ContactParameters::spinFrictionSpec;
                o.spinFriction = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--sticking-friction") {
                const auto& spec = contact::ContactParameters::stickingFrictionSpec;
                o.stickingFriction = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--sweep") {
                o.sweep = bench::parseList(flag, value, -1.0, 1.0).front();
            } else if (flag == "--root") {
                o.root = bench::parseList(flag, value, 0.0, 0.3).front();
            } else if (flag == "--turn-rate") {
                o.turnRate = bench::parseList(flag, value, -10.0, 10.0).front();
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --seconds, --spin-friction, --sticking-friction, "
                                            "--turn-rate, --sweep, --root)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "loop_reduction: %s\n", error.what());
        return 2;
    }
    const Reduction r = run(o);
    std::printf("expert into the redundant sigmoid (sweep %g, root %g m), %.1f s; spinFriction %g, "
                "stickingFriction %g, turn %g rad/s\n",
                o.sweep, o.root, o.seconds, o.spinFriction, o.stickingFriction, o.turnRate);
    std::printf("%-14s %10s %10s %12s %8s %9s %10s %10s %7s\n", "loop", "from_s", "undone_s", "turned_rad",
                "cross", "peak_F_N", "peak_T_Nm", "furthest_m", "finite");
    std::printf("%-14s %10.2f %10.2f %12.2f %8d %9.1f %10.3f %10.3f %7s\n",
                r.kind.empty() ? "-" : r.kind.c_str(), r.loopFrom, r.loopUntil, r.turnedInLoop,
                r.crossingsAfter, r.peakForce, r.peakTorque, r.furthest, r.finite ? "yes" : "no");
    return r.finite ? 0 : 1;
}
