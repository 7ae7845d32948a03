// A crossed sigmoid loop from the mechanics alone (issue 3): the novice's
// straight push into a redundant sigmoid (66 cm, its mesocolon 8.9 cm) on a
// haustrated wall (tissue.haustralAxialRatio 0.07, as in
// HaustralWallLoopTest.cpp) with the step guard at 10 mm, for 22 s, the
// sigmoid hung two ways:
//   - from one root line 17 cm long (anatomy.sigmoidRootLength, the chord
//     between the sigmoid's two ends): its loop swings round the root and
//     the shaft crosses itself where it leaves the sigmoid, a crossing the
//     colon at rest does not have; the loop is read as an alpha: it turns
//     clockwise in the anterior view, with the shaft that leaves the
//     sigmoid passing behind the shaft that enters it (right-handed, a
//     clockwise spiral along the shaft, LoopDetector.h);
//   - from a point behind each ring (the default): the shaft bows the
//     sigmoid into an N loop, and where it crosses itself it crosses where
//     the colon's own path does (the redundant sigmoid's curl at rest, right-
//     handed): no crossing of the loop's own, and the loop is typed by the
//     shaft's crossing there, an alpha.
// And the same sigmoid swept the other way (anatomy.sigmoidSweep -1: first
// to the patient's left, counter-clockwise on an anterior view), on the
// 17 cm root: at rest its limbs already cross, left-handed (the limb that
// leaves the sigmoid behind); the push stores shaft in it, and the loop is
// typed by the shaft's crossing there: a reverse alpha. The expert backs off
// that one turning counter-clockwise, and it comes undone sooner than by
// withdrawing alone.
// Labelled slow: three 22 s procedures, one per test, and two of the expert.

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
    double crossedTypeAt = -1.0;         ///< s: when an alpha or reverse alpha was first held
    double sharedAt = -1.0;        ///< s: the first analysis with a crossing shared with the colon at rest
    int mostShared = 0;            ///< the most crossings shared with the colon at rest in one analysis
    int sharedHandednessThen = 0;  ///< their handedness at the first reading with one
    double mostStored = 0.0;       ///< m, the most excess or stored shaft
    double deepest = 0.0;          ///< m, the deepest contact point
    int stepsDeep = 0;             ///< steps with a contact point more than a scope diameter in
    looptest::RunSummary summary;
};

/// The redundant sigmoid hung from a root `rootLength` long (0: behind each
/// ring) and swept `sweep` (anatomy.sigmoidSweep).
geometry::ColonAnatomy redundantSigmoidColon(double rootLength, double sweep)
{
    geometry::AnatomyParameters redundant = looptest::redundantSigmoid();
    redundant.sigmoidRootLength = rootLength;
    redundant.sigmoidSweep = sweep;
    return geometry::buildProceduralColon(redundant);
}

/// The haustrated wall and the step guard at 10 mm.
procedure::ProcedureSettings haustratedAndGuarded()
{
    procedure::ProcedureSettings settings;
    settings.tissue.haustralAxialRatio = 0.07;
    settings.scope.maxNodeStep = 0.01;
    return settings;
}

PushOutcome pushIntoRedundantSigmoid(double rootLength, double sweep = 1.0)
{
    constexpr int kSteps = 22000;
    const geometry::ColonAnatomy anatomy = redundantSigmoidColon(rootLength, sweep);
    procedure::ProcedureLoop loop(anatomy, haustratedAndGuarded());
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    PushOutcome outcome;
    for (int s = 0; s < kSteps; ++s) {
        loop.step(novice.next(loop));
        looptest::observe(loop, outcome.summary);
        const procedure::LoopSignals& signals = loop.loops().signals();
        const procedure::LoopKind held = loop.loops().current();
        outcome.read.insert(held);
        if ((held == procedure::LoopKind::Alpha || held == procedure::LoopKind::ReverseAlpha) &&
            outcome.crossedTypeAt < 0.0) {
            outcome.crossedTypeAt = loop.time();
        }
        outcome.mostStored = std::max({outcome.mostStored, signals.excessShaft, signals.storedShaft});
        if (signals.crossings > 0 && outcome.crossedAt < 0.0) {
            outcome.crossedAt = loop.time();
            outcome.handednessThen = signals.handedness;
        }
        outcome.mostCrossings = std::max(outcome.mostCrossings, signals.crossings);
        if (signals.sharedCrossings > 0 && outcome.sharedAt < 0.0) {
            outcome.sharedAt = loop.time();
            outcome.sharedHandednessThen = signals.sharedHandedness;
        }
        outcome.mostShared = std::max(outcome.mostShared, signals.sharedCrossings);
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
    ::testing::Test::RecordProperty("shared_at_s", std::to_string(o.sharedAt));
    ::testing::Test::RecordProperty("crossed_type_at_s", std::to_string(o.crossedTypeAt));
    ::testing::Test::RecordProperty("most_shared_crossings", std::to_string(o.mostShared));
    ::testing::Test::RecordProperty("shared_handedness_then", std::to_string(o.sharedHandednessThen));
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

/// Records the push's figures and checks what every push here must show: a
/// finite run storing a loop's worth of shaft, held inside the wall, under a
/// real operator's peak push.
void recordAStableLoop(const PushOutcome& o)
{
    record(o);
    EXPECT_TRUE(o.summary.finite);
    EXPECT_GT(o.mostStored, kThreshold);
    EXPECT_LT(o.stepsDeep, kStepsDeep);
    EXPECT_LT(o.summary.peakHandleForce, kOperatorPeak);
}

TEST(SigmoidLoop, ASigmoidOnANarrowRootSwingsIntoACrossedLoopReadAsAnAlpha)
{
    const PushOutcome o = pushIntoRedundantSigmoid(0.17);
    recordAStableLoop(o);
    EXPECT_GT(o.crossedAt, 0.0) << "the shaft crossed itself where the colon at rest does not";
    EXPECT_GT(o.handednessThen, 0) << "right-handed: the shaft leaving the sigmoid passes behind";
    EXPECT_TRUE(o.read.count(procedure::LoopKind::Alpha) == 1);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::ReverseAlpha) == 0);
}

TEST(SigmoidLoop, ASigmoidHungBehindEachRingBowsIntoALoopThatCrossesOnlyWhereTheColonDoes)
{
    const PushOutcome o = pushIntoRedundantSigmoid(0.0);
    recordAStableLoop(o);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::N) == 1) << "bowed before its shaft crossed";
    EXPECT_EQ(o.mostCrossings, 0);
    EXPECT_GE(o.mostShared, 1) << "the shaft crosses itself where the sigmoid's curl at rest does";
    EXPECT_GT(o.sharedHandednessThen, 0) << "that curl is right-handed";
    EXPECT_TRUE(o.read.count(procedure::LoopKind::Alpha) == 1);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::ReverseAlpha) == 0);
}

TEST(SigmoidLoop, ASigmoidSweptToTheLeftOnANarrowRootIsPushedIntoAReverseAlphaLoop)
{
    const PushOutcome o = pushIntoRedundantSigmoid(0.17, -1.0);
    recordAStableLoop(o);
    EXPECT_GE(o.mostShared, 1) << "the shaft crosses itself where the sigmoid at rest does";
    EXPECT_LT(o.sharedHandednessThen, 0) << "left-handed: the shaft leaving the sigmoid passes behind";
    EXPECT_TRUE(o.read.count(procedure::LoopKind::ReverseAlpha) == 1);
    EXPECT_TRUE(o.read.count(procedure::LoopKind::Alpha) == 0);
}

struct Reduction {
    double loopFrom = -1.0;   ///< s: when the reverse alpha was first held; < 0: never
    double loopUntil = -1.0;  ///< s: when it was last held
    /// rad: the handle's rotation summed over the steps the loop was held (+ = counter-clockwise)
    double turnedInLoop = 0.0;
    int crossingsAfter = -1;  ///< own and shared crossings at the first analysis after the loop
    std::set<procedure::LoopKind> held;
    looptest::RunSummary summary;
};

/// The expert into the left-swept sigmoid on the 17 cm root, reducing loops
/// with its shaft turned at `turnRate` (OperatorStyle::reductionTurnRate),
/// until the shaft has crossed itself nowhere for 3 s after the reverse alpha
/// it formed (at most `seconds`).
Reduction reduceTheReverseAlpha(double turnRate, double seconds)
{
    const geometry::ColonAnatomy anatomy = redundantSigmoidColon(0.17, -1.0);
    const procedure::ProcedureSettings settings = haustratedAndGuarded();
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::OperatorStyle style = procedure::expertStyle();
    style.reductionTurnRate = turnRate;
    procedure::ScriptedOperator expert(style);
    Reduction r;
    double rotation = 0.0;
    const auto steps = static_cast<int>(seconds / settings.stepping.loopStep);
    double uncrossedSince = -1.0;  // s: since when no crossing and no reverse alpha; < 0: not now
    for (int s = 0; s < steps && !expert.finished(); ++s) {
        if (r.loopFrom >= 0.0 && uncrossedSince >= 0.0 && loop.time() > uncrossedSince + 3.0) {
            break;
        }
        const procedure::InputSample input = expert.next(loop);
        if (loop.loops().current() == procedure::LoopKind::ReverseAlpha) {
            r.turnedInLoop += input.rotation - rotation;
        }
        rotation = input.rotation;
        loop.step(input);
        looptest::observe(loop, r.summary);
        const procedure::LoopKind held = loop.loops().current();
        const procedure::LoopSignals& signals = loop.loops().signals();
        const int crossings = signals.crossings + signals.sharedCrossings;
        r.held.insert(held);
        if (held == procedure::LoopKind::ReverseAlpha) {
            r.loopFrom = r.loopFrom < 0.0 ? loop.time() : r.loopFrom;
            r.loopUntil = loop.time();
            r.crossingsAfter = -1;
        } else if (r.loopFrom >= 0.0 && r.crossingsAfter < 0) {
            r.crossingsAfter = crossings;
        }
        if (held == procedure::LoopKind::ReverseAlpha || crossings > 0) {
            uncrossedSince = -1.0;
        } else if (uncrossedSince < 0.0) {
            uncrossedSince = loop.time();
        }
    }
    return r;
}

TEST(SigmoidLoop, TheExpertBacksOffTheReverseAlphaTurningCounterClockwiseAndItComesUndoneSooner)
{
    // The expert's insertion into the sigmoid of the test above: it steers
    // in, reads the reverse alpha, backs off turning counter-clockwise
    // (ScriptedOperator's reductionTurn), and the shaft's crossing comes
    // undone. The turn does it, not the withdrawal alone: the same expert
    // withdrawing without turning undoes it later (62.0 s against 49.9 s,
    // and 64.7 s turning clockwise, build/bench/loop_reduction). Turning the
    // handle counter-clockwise while the shaft beyond is held adds
    // right-handed link to the shaft, which undoes its left-handed writhe
    // (LoopDetector.h).
    constexpr double kSeconds = 70.0;
    const Reduction r = reduceTheReverseAlpha(procedure::expertStyle().reductionTurnRate, kSeconds);
    const Reduction unturned = reduceTheReverseAlpha(0.0, kSeconds);
    ::testing::Test::RecordProperty("reverse_alpha_from_s", std::to_string(r.loopFrom));
    ::testing::Test::RecordProperty("reverse_alpha_until_s", std::to_string(r.loopUntil));
    ::testing::Test::RecordProperty("turned_in_loop_rad", std::to_string(r.turnedInLoop));
    ::testing::Test::RecordProperty("crossings_after", std::to_string(r.crossingsAfter));
    ::testing::Test::RecordProperty("peak_handle_force_N", std::to_string(r.summary.peakHandleForce));
    ::testing::Test::RecordProperty("unturned_until_s", std::to_string(unturned.loopUntil));
    EXPECT_TRUE(r.summary.finite);
    ASSERT_GT(r.loopFrom, 0.0) << "the expert's insertion forms the reverse alpha too";
    EXPECT_LT(r.loopUntil, kSeconds - 1.0) << "and the reverse alpha is undone";
    EXPECT_GT(r.turnedInLoop, 1.0) << "by turning counter-clockwise (positive), at least a sixth of a turn";
    EXPECT_EQ(r.crossingsAfter, 0) << "the shaft no longer crosses itself";
    EXPECT_TRUE(r.held.count(procedure::LoopKind::Alpha) == 0);
    EXPECT_LT(r.summary.peakHandleForce, kOperatorPeak);
    ASSERT_GT(unturned.loopFrom, 0.0);
    EXPECT_NEAR(unturned.loopFrom, r.loopFrom, 0.5) << "s: the same insertion up to the reduction";
    EXPECT_LT(r.loopUntil, unturned.loopUntil - 5.0)
        << "the turn undoes the loop sooner than withdrawing alone";
}

}  // namespace
