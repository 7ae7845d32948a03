// A loop from the mechanics alone (issue 3): the novice's straight push into
// a redundant sigmoid (66 cm, as in incomplete examinations; its mesocolon
// 8.9 cm, one SD above the mean) for 18 s, the tip then about 1 m along the
// colon, with the wall as a flat membrane and as a haustrated one
// (tissue.haustralAxialRatio 0.07: the tube a sixth of the scope's bending
// rigidity; Calibration.AHaustralWallIsSofterAlongAndInBendingButNotAround).
// Labelled slow: two 18 s procedures.
//
// The flat wall's tube is over twice as stiff in bending as the scope and
// guides it like a pipe: the shaft runs on along the colon and no loop is
// read. The haustrated wall gives way: the shaft bows the sigmoid and an N
// loop is read (no crossing, so not an alpha loop). Measured: flat, the most
// excess shaft in a segment 4.4 cm, no loop, the tip 1.057 m along the colon
// at 18 s; haustrated, the N loop read at 14.150 s, up to 11.5 cm of excess
// shaft in the sigmoid, the tip 0.996 m along. The threshold is 8 cm.

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace {

using namespace colonosim;

struct PushOutcome {
    double mostExcess = 0.0;    ///< m, the most excess shaft in one segment
    double firstLoopAt = -1.0;  ///< s; < 0: no loop read
    procedure::LoopKind firstLoop = procedure::LoopKind::None;
    procedure::LoopKind finalLoop = procedure::LoopKind::None;
    double furthest = 0.0;  ///< m, the tip along the colon
};

PushOutcome pushIntoRedundantSigmoid(double haustralAxialRatio)
{
    constexpr int kSteps = 18000;
    geometry::AnatomyParameters redundant;
    redundant.sigmoidLength = 0.66;
    redundant.sigmoidMesenteryHeight = 0.089;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(redundant);
    procedure::ProcedureSettings settings;
    settings.tissue.haustralAxialRatio = haustralAxialRatio;
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    PushOutcome outcome;
    for (int s = 0; s < kSteps; ++s) {
        loop.step(novice.next(loop));
        outcome.mostExcess = std::max(outcome.mostExcess, loop.loops().signals().excessShaft);
        outcome.furthest = std::max(outcome.furthest, loop.lastFrame().tipArcLength);
        if (outcome.firstLoopAt < 0.0 && loop.loops().current() != procedure::LoopKind::None) {
            outcome.firstLoopAt = loop.time();
            outcome.firstLoop = loop.loops().current();
        }
    }
    outcome.finalLoop = loop.loops().current();
    return outcome;
}

TEST(HaustralWall, AStraightPushIntoARedundantSigmoidFormsAnNLoopOnlyWhenTheWallGivesWay)
{
    const double threshold = procedure::LoopParameters{}.threshold;
    const PushOutcome flat = pushIntoRedundantSigmoid(1.0);
    const PushOutcome haustral = pushIntoRedundantSigmoid(0.07);
    for (const auto& [name, run] : {std::pair{"flat", flat}, std::pair{"haustral", haustral}}) {
        std::printf(
            "%s wall: most excess %.1f cm, first loop %s at %.3f s, loop at the end %s, furthest %.3f m\n",
            name, run.mostExcess * 100, std::string(procedure::loopName(run.firstLoop)).c_str(),
            run.firstLoopAt, std::string(procedure::loopName(run.finalLoop)).c_str(), run.furthest);
    }

    EXPECT_LT(flat.firstLoopAt, 0.0) << "a loop was read at " << flat.firstLoopAt << " s";
    EXPECT_LT(flat.mostExcess, threshold) << "m of excess shaft";

    EXPECT_EQ(haustral.firstLoop, procedure::LoopKind::N);
    EXPECT_GT(haustral.firstLoopAt, 10.0) << "s: the tip was in the sigmoid's first half before";
    EXPECT_EQ(haustral.finalLoop, procedure::LoopKind::N);
    EXPECT_GT(haustral.mostExcess, threshold + 0.02) << "m of excess shaft";
    // The loop stores shaft the flat wall's run turned into progress.
    EXPECT_LT(haustral.furthest, flat.furthest) << "m along the colon";
}

}  // namespace
