// A crossed sigmoid loop from the mechanics alone (issue 3): the novice's
// straight push into a redundant sigmoid (66 cm, its mesocolon 8.9 cm) on a
// haustrated wall (tissue.haustralAxialRatio 0.07, as in
// HaustralWallLoopTest.cpp) with the step guard at 10 mm, for 22 s, the
// sigmoid hung two ways:
//   - from one root line 17 cm long (anatomy.sigmoidRootLength, the chord
//     between the sigmoid's two ends): its loop swings round the root and
//     the shaft crosses itself where it leaves the sigmoid, a crossing the
//     colon at rest does not have; the loop is read as a reverse alpha: it
//     turns clockwise in the anterior view, with the shaft that leaves the
//     sigmoid passing behind the shaft that enters it (right-handed);
//   - from a point behind each ring (the default): the shaft bows the
//     sigmoid into an N loop, and where it crosses itself it crosses where
//     the colon's own path does (the redundant sigmoid's curl at rest), so
//     no crossing of a loop is read.
// Labelled slow: two 22 s procedures, one per test.

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/scope/ScopeParameters.h"
#include "tests/procedure/LoopObservation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace {

using namespace colonosim;

constexpr double kThreshold = 0.08;     // m, loops.threshold
constexpr double kOperatorPeak = 43.0;  // N, real operators' peak push (Appleyard et al. 2000)
const double kScopeDiameter = scope::ScopeParameters{}.outerDiameter;  // m
constexpr int kStepsDeep =
    50;  // steps with a contact point more than a scope diameter in (as HaustralWall's)

struct PushOutcome {
    std::set<procedure::LoopKind> read;  ///< every loop type the detector held
    double crossedAt = -1.0;             ///< s: the first analysis with a loop's own crossing; < 0: none
    int mostCrossings = 0;               ///< the most own crossings in one analysis
    int handednessThen = 0;              ///< their handedness at the first crossed reading
    double mostStored = 0.0;             ///< m, the most excess or stored shaft
    double deepest = 0.0;                ///< m, the deepest contact point
    int stepsDeep = 0;                   ///< steps with a contact point more than a scope diameter in
    looptest::RunSummary summary;
};

PushOutcome pushIntoRedundantSigmoid(double rootLength)
{
    constexpr int kSteps = 22000;
    geometry::AnatomyParameters redundant = looptest::redundantSigmoid();
    redundant.sigmoidRootLength = rootLength;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(redundant);
    procedure::ProcedureSettings settings;
    settings.tissue.haustralAxialRatio = 0.07;
    settings.scope.maxNodeStep = 0.01;
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    PushOutcome outcome;
    for (int s = 0; s < kSteps; ++s) {
        loop.step(novice.next(loop));
        looptest::observe(loop, outcome.summary);
        const procedure::LoopSignals& signals = loop.loops().signals();
        outcome.read.insert(loop.loops().current());
        outcome.mostStored = std::max({outcome.mostStored, signals.excessShaft, signals.storedShaft});
        if (signals.crossings > 0 && outcome.crossedAt < 0.0) {
            outcome.crossedAt = loop.time();
            outcome.handednessThen = signals.handedness;
        }
        outcome.mostCrossings = std::max(outcome.mostCrossings, signals.crossings);
        double deepest = 0.0;
        for (const contact::LumenNodeContact& c : loop.lumen().contacts()) {
            deepest = std::max(deepest, c.depth);
        }
        outcome.deepest = std::max(outcome.deepest, deepest);
        outcome.stepsDeep += deepest > kScopeDiameter ? 1 : 0;
    }
    return outcome;
}

void record(const PushOutcome& o)
{
    ::testing::Test::RecordProperty("crossed_at_s", std::to_string(o.crossedAt));
    ::testing::Test::RecordProperty("most_crossings", std::to_string(o.mostCrossings));
    ::testing::Test::RecordProperty("handedness_then", std::to_string(o.handednessThen));
    ::testing::Test::RecordProperty("most_stored_m", std::to_string(o.mostStored));
    ::testing::Test::RecordProperty("deepest_mm", std::to_string(o.deepest * 1e3));
    ::testing::Test::RecordProperty("steps_deep", std::to_string(o.stepsDeep));
    ::testing::Test::RecordProperty("peak_handle_force_N", std::to_string(o.summary.peakHandleForce));
    std::string kinds;
    for (procedure::LoopKind k : o.read) {
        kinds += std::string(procedure::loopName(k)) + " ";
    }
    ::testing::Test::RecordProperty("loops_read", kinds);
}

TEST(SigmoidLoop, ASigmoidOnANarrowRootSwingsIntoACrossedLoopReadAsAReverseAlpha)
{
    const PushOutcome o = pushIntoRedundantSigmoid(0.17);
    record(o);
    EXPECT_TRUE(o.summary.finite);
    EXPECT_GT(o.mostStored, kThreshold);
    EXPECT_GT(o.crossedAt, 0.0) << "the shaft crossed itself where the colon at rest does not";
    EXPECT_GT(o.handednessThen, 0) << "right-handed: the shaft leaving the sigmoid passes behind";
    EXPECT_TRUE(o.read.count(procedure::LoopKind::ReverseAlpha) == 1);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::Alpha) == 0);
    EXPECT_LT(o.stepsDeep, kStepsDeep);
    EXPECT_LT(o.summary.peakHandleForce, kOperatorPeak);
}

TEST(SigmoidLoop, ASigmoidHungBehindEachRingBowsIntoAnNLoopWithoutACrossingOfItsOwn)
{
    const PushOutcome o = pushIntoRedundantSigmoid(0.0);
    record(o);
    EXPECT_TRUE(o.summary.finite);
    EXPECT_GT(o.mostStored, kThreshold);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::N) == 1);
    EXPECT_EQ(o.mostCrossings, 0);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::Alpha) == 0);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::ReverseAlpha) == 0);
    EXPECT_LT(o.stepsDeep, kStepsDeep);
    EXPECT_LT(o.summary.peakHandleForce, kOperatorPeak);
}

}  // namespace
