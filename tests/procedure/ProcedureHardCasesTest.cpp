// Hard cases of the procedure loop that run whole procedures for seconds
// (labelled slow: under the sanitizers the loop runs about 33 times slower).
//   - A case's adhesions act in the loop, and an insertion pushed on against
//     a fixed adhesion stays stable.
//   - A scope hooked and pushed with torque in a redundant sigmoid, then twisted hard at the handle
//     both ways, stays stable.
//   - A shaft that springs forward against the closed cecal end does not carry its tip through it.

#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/TissueParameters.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/procedure/WallSite.h"
#include "tests/procedure/HookedCase.h"
#include "tests/procedure/LoopObservation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace colonosim;
using looptest::defaultColon;
using procedure::ProcedureLoop;
using procedure::ProcedureSettings;
using procedure::WallSite;

/// m along the default colon: the middle of its sigmoid.
double midSigmoid()
{
    const geometry::Centreline& colon = defaultColon().centreline;
    double first = -1.0;
    double last = -1.0;
    for (double s = 0.0; s < colon.length(); s += 0.002) {
        if (geometry::sampleCentreline(colon, s).segment == geometry::Segment::Sigmoid) {
            first = first < 0.0 ? s : first;
            last = s;
        }
    }
    return 0.5 * (first + last);
}

/// A whole ring of the wall bound at `arc`: eight places round the clock.
std::vector<WallSite> boundRing(double arc)
{
    std::vector<WallSite> sites;
    for (int k = 0; k < 8; ++k) {
        sites.push_back(WallSite{arc, 2.0 * std::numbers::pi * k / 8.0});
    }
    return sites;
}

// The adhesions' anchors act in the loop: the same mid-sigmoid ring, pulled
// on by the novice's first 6 s, moves less when adhesions hold it (measured:
// 131 mm free, 2.2 mm at the default adhesion stiffness of 500 N/m).
TEST(Adhesions, AnAdhesionHoldsItsWallNodeInTheLoop)
{
    const std::vector<WallSite> ring = boundRing(midSigmoid());
    std::vector<int> nodes;
    for (size_t k = 0; k < ring.size(); ++k) {
        nodes.push_back(procedure::wallNodeAt(defaultColon(), ring[k], "ring"));
    }
    double moved[2] = {0.0, 0.0};  // m, largest displacement of a ring node from the start
    for (int withAdhesions = 0; withAdhesions < 2; ++withAdhesions) {
        ProcedureSettings settings;
        if (withAdhesions != 0) {
            settings.adhesions = ring;
        }
        ProcedureLoop loop(defaultColon(), settings);
        const Eigen::Matrix3Xd start = loop.colon().body.positions();
        procedure::ScriptedOperator novice(procedure::noviceStyle());
        for (int s = 0; s < 6000; ++s) {
            loop.step(novice.next(loop));
            for (const int node : nodes) {
                moved[withAdhesions] = std::max(
                    moved[withAdhesions], (loop.colon().body.positions().col(node) - start.col(node)).norm());
            }
        }
    }
    RecordProperty("free_mm", std::to_string(moved[0] * 1e3));
    RecordProperty("adhered_mm", std::to_string(moved[1] * 1e3));
    EXPECT_LT(moved[1], 0.5 * moved[0])
        << "mm moved: free " << moved[0] * 1e3 << ", adhered " << moved[1] * 1e3;
}

// Hard case (issue 3): an insertion pushed on against a fixed adhesion. A
// whole mid-sigmoid ring is bound at the top of the adhesion stiffness's
// range, and the novice, which pushes through resistance at 6 cm/s without
// waiting to aim, drives for 15 s. Asserted: everything stays finite; the
// tissue's step check engages in few steps; the tip stays inside the lumen
// but for a few milliseconds; the handle force stays bounded; and the ring
// holds, within millimetres of where it started. Measured: no step check
// engaged, the tip never more than 1.1 mm into the wall, 4.8 N at the
// handle at most, the ring 0.44 mm from where it started, and the tip
// 0.92 m along the colon at 15 s, past the adhesion.
TEST(Adhesions, AnInsertionPushedAgainstAFixedAdhesionStaysStable)
{
    constexpr int kSteps = 15000;         // 15 s at 1 kHz
    constexpr int kEngagedLimit = 15;     // steps in which the step check rejected a try (of 15,000)
    constexpr int kStepsOutside = 50;     // steps with the tip more than a scope diameter in
    constexpr double kForceLimit = 25.0;  // N at the handle: the haptic device's limit
    constexpr double kHeld = 5e-3;        // m, how far a bound node may move
    ProcedureSettings settings;
    settings.tissue.adhesionStiffness = physics::TissueParameters::adhesionSpec.maxValue;
    settings.adhesions = boundRing(midSigmoid());
    std::vector<int> nodes;
    for (const WallSite& site : settings.adhesions) {
        nodes.push_back(procedure::wallNodeAt(defaultColon(), site, "ring"));
    }
    ProcedureLoop loop(defaultColon(), settings);
    const Eigen::Matrix3Xd start = loop.colon().body.positions();
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    looptest::RunSummary summary;
    const double diameter = settings.scope.outerDiameter;
    int engaged = 0;
    int outside = 0;
    double deepest = 0.0;
    double moved = 0.0;
    double furthest = 0.0;
    for (int s = 0; s < kSteps; ++s) {
        const long triesBefore = loop.tissue().rejectedSteps();
        loop.step(novice.next(loop));
        engaged += loop.tissue().rejectedSteps() > triesBefore ? 1 : 0;
        looptest::observe(loop, summary);
        const double depth = loop.lumen().contacts().back().depth;
        outside += depth > diameter ? 1 : 0;
        deepest = std::max(deepest, depth);
        furthest = std::max(furthest, loop.lastFrame().tipArcLength);
        for (const int node : nodes) {
            moved = std::max(moved, (loop.colon().body.positions().col(node) - start.col(node)).norm());
        }
    }
    RecordProperty("engaged_steps", std::to_string(engaged));
    RecordProperty("steps_outside", std::to_string(outside));
    RecordProperty("deepest_mm", std::to_string(deepest * 1e3));
    RecordProperty("peak_handle_force_N", std::to_string(summary.peakHandleForce));
    RecordProperty("ring_moved_mm", std::to_string(moved * 1e3));
    RecordProperty("furthest_m", std::to_string(furthest));
    EXPECT_TRUE(summary.finite);
    EXPECT_LT(engaged, kEngagedLimit);
    EXPECT_LT(outside, kStepsOutside) << "deepest " << deepest * 1e3 << " mm";
    EXPECT_LT(summary.peakHandleForce, kForceLimit);
    EXPECT_LT(moved, kHeld) << "mm the bound ring moved";
    EXPECT_GT(furthest, midSigmoid()) << "the scope was pushed past the adhesion";
}

// Hard case (issue 3): a hooked shaft pushed with torque, then twisted hard. A
// redundant sigmoid (66 cm, as in incomplete examinations; its mesocolon
// 8.9 cm, one SD above the mean) takes the novice's insertion for 15 s; then
// the tip is hooked with the up/down dial at its stop and the shaft pushed on
// at 5 cm/s while it is turned clockwise (seen from the operator) at 1 rad/s
// for 7 s, which
// takes the shaft's coronal turning in the sigmoid more than a whole turn
// away from the colon's rest path over the same stretch; then, with the
// insertion held,
// the handle is twisted a whole turn counter-clockwise in 1 s and back in
// 1 s. (The turns were labelled the other way round until the shaft's
// rotation took the operator's convention, README "Which way the shaft
// turns"; the turns themselves, and so the figures below, are unchanged.)
// Asserted: everything stays finite; the tissue's step check engages in few
// steps; while the shaft is twisted the tip stays inside the lumen but
// for a few milliseconds, and it is inside at the end; the handle's force and
// torque stay within the haptic device's limits; and the shaft's shape
// really left the colon's rest path by more than a turn. Measured: no step
// check engaged, 14.7 N at most, the turning beyond the path over the
// insertion tube 6.59 rad at most (read over the left colon's shaft; 6.50
// over the sigmoid's alone before that; 9.01 with the bending section, which the
// loop detector leaves out), no step outside while twisted, the tip
// 0.17 mm in at the end. The handle's torque stays within the device's 1 N m
// while the novice inserts; from the curl on it is bounded by the torque of
// the shaft with its tip held still (GJ theta / L). Since the contact's load
// may grow by the way a node came in (ContactCoupling.h), the wall holds the
// hooked tip while the handle turns: 1.76 N m at most in the curl (0.895 N m
// before that, with the tip slipping) and 0.69 N m while twisted. Not
// asserted, and in docs/known-limits.md: while the hooked tip is pushed
// on, it is driven up to 41.2 mm into the wall for 316 steps, as a blind push
// against a bend does. The turning beyond the path is not a curl of the
// shaft: its own coronal turning there goes from -7.05 rad (following the redundant sigmoid's
// clockwise spiral at rest, -7.1 rad) to about -0.8 rad within 0.5 s, 18 s
// in, and stays there: the push straightens the sigmoid's spiral, or its
// projection flips by 2 pi where the shaft is seen end-on
// (docs/known-limits.md). No curl is read (no alpha loop), rightly. The shaft pushed in
// behind the held tip bows the redundant sigmoid on its mesocolon, and the
// colon moves with it: the loop is read from the insertion against the tip's
// place along the colon (LoopDetector's stored shaft), an N loop in the
// sigmoid, from the mechanics alone. Asserted: no loop is read while the
// novice inserts, and one is read while the hooked tip is pushed on.
// Measured (the stored shaft at the base of the bending section): 3.0 cm
// stored when the push begins, 9.2 cm at most in the push (the detector's
// threshold is 8 cm), the loop read 0.86 s into it; the rest of the 35 cm
// pushed carried the tip on along the colon and into the wall.
TEST(HardCases, AHookedShaftPushedWithTorqueInARedundantSigmoidTwistedHardStaysStable)
{
    constexpr int kEngagedLimit = 25;     // steps in which the step check rejected a try
    constexpr int kStepsOutside = 50;     // steps with the tip more than a scope diameter in
    constexpr double kForceLimit = 25.0;  // N at the handle: the haptic device's limit
    constexpr double kTorqueLimit = 1.0;  // N m at the handle: the CSIRO device's rotational limit
    const geometry::AnatomyParameters redundant = looptest::redundantSigmoid();
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(redundant);
    const ProcedureSettings settings;
    ProcedureLoop loop(anatomy, settings);
    looptest::RunSummary summary;
    const double diameter = settings.scope.outerDiameter;
    int engaged = 0;
    int outside = 0;
    double deepest = 0.0;
    std::array<double, 3> peakTorque{};  // N m in the insertion, the curl and the twist
    double mostTurned = 0.0;             // rad the handle turned from where the curl began, at most
    double mostTurning = 0.0;            // rad, the shaft's coronal turning beyond the colon's rest path
    double mostStored = 0.0;             // m, the stored shaft (insertion against the tip's place), at most
    double storedAtPush = 0.0;           // m, the stored shaft when the hooked push begins
    double loopReadAt = -1.0;            // s, when a loop was first read in the push; < 0: never
    bool loopInInsertion = false;        // a loop was read while the novice inserted
    std::array<int, 3> outsideIn{};      // steps outside in the insertion, the curl and the twist
    looptest::HookedCaseDriver driver;
    for (int s = 0; s < looptest::kHookedSteps; ++s) {
        const procedure::InputSample input = driver.next(loop);
        const procedure::InputSample& held = driver.held();
        const long triesBefore = loop.tissue().rejectedSteps();
        loop.step(input);
        engaged += loop.tissue().rejectedSteps() > triesBefore ? 1 : 0;
        looptest::observe(loop, summary);
        const double depth = loop.lumen().contacts().back().depth;
        outside += depth > diameter ? 1 : 0;
        const size_t phase = driver.phase();
        outsideIn[phase] += depth > diameter ? 1 : 0;
        deepest = std::max(deepest, depth);
        peakTorque[phase] = std::max(peakTorque[phase], std::abs(loop.outputs().handleTorque));
        mostTurned = phase > 0 ? std::max(mostTurned, std::abs(input.rotation - held.rotation)) : 0.0;
        if (loop.loops().signals().segment == geometry::Segment::Sigmoid) {
            mostTurning = std::max(mostTurning, loop.loops().signals().turning);
        }
        storedAtPush = phase == 0 ? loop.loops().signals().storedShaft : storedAtPush;
        loopInInsertion =
            loopInInsertion || (phase == 0 && loop.loops().current() != procedure::LoopKind::None);
        mostStored = std::max(mostStored, phase == 1 ? loop.loops().signals().storedShaft : 0.0);
        if (phase == 1 && loop.loops().current() != procedure::LoopKind::None && loopReadAt < 0.0) {
            loopReadAt = loop.time();
        }
    }
    RecordProperty("engaged_steps", std::to_string(engaged));
    RecordProperty("steps_outside", std::to_string(outside));
    RecordProperty("steps_outside_by_phase", std::to_string(outsideIn[0]) + " " +
                                                 std::to_string(outsideIn[1]) + " " +
                                                 std::to_string(outsideIn[2]));
    RecordProperty("end_depth_mm", std::to_string(loop.lumen().contacts().back().depth * 1e3));
    RecordProperty("deepest_mm", std::to_string(deepest * 1e3));
    RecordProperty("peak_handle_force_N", std::to_string(summary.peakHandleForce));
    RecordProperty("peak_handle_torque_by_phase_Nm", std::to_string(peakTorque[0]) + " " +
                                                         std::to_string(peakTorque[1]) + " " +
                                                         std::to_string(peakTorque[2]));
    RecordProperty("most_turning_rad", std::to_string(mostTurning));
    RecordProperty("stored_at_push_m", std::to_string(storedAtPush));
    RecordProperty("most_stored_m", std::to_string(mostStored));
    RecordProperty("loop_read_at_s", std::to_string(loopReadAt));
    EXPECT_TRUE(summary.finite);
    EXPECT_LT(engaged, kEngagedLimit);
    EXPECT_LT(outsideIn[2], kStepsOutside)
        << "steps with the tip more than a scope diameter in while twisted";
    EXPECT_LT(loop.lumen().contacts().back().depth, diameter) << "the tip is inside the lumen at the end";
    EXPECT_LT(summary.peakHandleForce, kForceLimit);
    EXPECT_LT(peakTorque[0], kTorqueLimit);
    // Turned at the handle from the curl on, the torque is at most the
    // shaft's own with its tip held still all the while: GJ theta / L, with
    // the most the handle turned (7 rad) and the least shaft inserted (the
    // curl's start). The device clamps what it renders at its 1 N m; more
    // than a held tip's would be torque the contact made.
    const double heldTip = settings.scope.torsionalRigidity * mostTurned / driver.held().insertion;
    RecordProperty("held_tip_torque_Nm", std::to_string(heldTip));
    EXPECT_LT(std::max(peakTorque[1], peakTorque[2]), heldTip) << "N m, against a held tip's";
    EXPECT_GT(mostTurning, 2.0 * std::numbers::pi)
        << "rad the shaft's coronal turning left the colon's rest path by in the sigmoid";
    EXPECT_GT(loopReadAt, 0.0) << "no loop was read while the hooked tip was pushed on";
    EXPECT_FALSE(loopInInsertion) << "a loop was read before the hooked tip was pushed";
}

// Hard case (issue 3: no tunnelling): the tip driven into the closed cecal
// end by the shaft behind it, not by the insertion. On generated patient 1
// (a 1.113 m colon) the novice reaches the cecum at about 16.4 s and keeps
// pushing; as the shaft's bends straighten under the push, the chain carries
// the tip forward at 3-7 m/s with the insertion held. The contact's load may
// grow each step by the way the tip came in as well as by its trust region
// (procedure/ContactCoupling.h). Before that, the tip passed through the cecal
// end within 9 ms and stayed up to 53 mm beyond it under 1-3 N (1,555 steps
// of the novice's 150 s more than a scope diameter in). Asserted over 18 s:
// the cecum is reached, the tip never more than a scope diameter into the
// wall, and the handle force within the haptic device's limit. Measured: the
// deepest 10.6 mm, at 13.09 s (the depth counts the scope's radius), and
// 19.7 N at the handle at most.
TEST(HardCases, AShaftSpringingForwardAgainstTheCecalEndDoesNotCarryItsTipThrough)
{
    constexpr int kSteps = 18000;         // 18 s at 1 kHz
    constexpr double kForceLimit = 25.0;  // N at the handle: the haptic device's limit
    const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(1));
    const ProcedureSettings settings = cases::procedureSettings(scene);
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    looptest::RunSummary summary;
    double deepest = 0.0;
    double deepestAt = 0.0;
    for (int s = 0; s < kSteps && !novice.finished(); ++s) {
        loop.step(novice.next(loop));
        looptest::observe(loop, summary);
        const double depth = loop.lumen().contacts().back().depth;
        if (depth > deepest) {
            deepest = depth;
            deepestAt = loop.time();
        }
    }
    RecordProperty("deepest_mm", std::to_string(deepest * 1e3));
    RecordProperty("deepest_at_s", std::to_string(deepestAt));
    RecordProperty("peak_handle_force_N", std::to_string(summary.peakHandleForce));
    ASSERT_TRUE(summary.finite);
    EXPECT_TRUE(loop.cecumReached()) << "the novice no longer reaches the cecal end: the case tests nothing";
    EXPECT_LT(deepest, settings.scope.outerDiameter) << "m into the wall at " << deepestAt << " s";
    EXPECT_LT(summary.peakHandleForce, kForceLimit);
}

}  // namespace
