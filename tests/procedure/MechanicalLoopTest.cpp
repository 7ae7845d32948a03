// Loops that form from the mechanics (issue 3), not from a script: the
// inputs only push, turn and steer the scope, and the loop detector reads
// what the shaft and the colon did (labelled slow: each case runs the whole
// procedure loop for about 25 s of simulated time).

#include "simcore/procedure/LoopDetector.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "tests/procedure/LoopObservation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

using namespace colonosim;
using procedure::EventKind;
using procedure::LoopDetector;
using procedure::LoopKind;
using procedure::loopName;
using procedure::ProcedureLoop;
using procedure::ProcedureSettings;

/// Time of the first event of `kind` with `detail` at or after `from`; -1 if none.
double firstEvent(const procedure::Recording& recording, EventKind kind, const std::string& detail,
                  double from)
{
    for (const procedure::RecordedEvent& e : recording.events) {
        if (e.kind == kind && e.detail == detail && e.time >= from) {
            return e.time;
        }
    }
    return -1.0;
}

constexpr int kNovice = 15000;           // steps of the novice's insertion
constexpr int kCurl = 7000;              // steps of the hooked, turning push
constexpr int kWithdraw = 6000;          // steps of the withdrawal
constexpr double kWithdrawSpeed = 0.05;  // m/s

/// The novice's insertion into the redundant sigmoid, then the hooked push
/// with counter-clockwise torque; returns the last input of the push.
procedure::InputSample curlTheShaft(ProcedureLoop& loop, looptest::RunSummary& summary)
{
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    const double dt = ProcedureSettings{}.stepping.loopStep;
    procedure::InputSample held;
    for (int s = 0; s < kNovice; ++s) {
        held = novice.next(loop);
        loop.step(held);
        looptest::observe(loop, summary);
    }
    EXPECT_EQ(loopName(loop.loops().current()), loopName(LoopKind::None))
        << "after the novice's insertion, turning " << loop.loops().signals().turning << " rad";
    procedure::InputSample pushed;
    for (int s = 0; s < kCurl; ++s) {
        pushed = looptest::hookedCurl(held, s + 1, dt);
        loop.step(pushed);
        looptest::observe(loop, summary);
    }
    return pushed;
}

/// Step `step` (from 0) of a withdrawal at 5 cm/s from `pushed`, the dial
/// released, the shaft turned clockwise at `turnRate` (rad/s).
procedure::InputSample withdrawal(const procedure::InputSample& pushed, int step, double turnRate, double dt)
{
    procedure::InputSample input = pushed;
    input.dialUpDown = 0.0;
    input.insertion = pushed.insertion - kWithdrawSpeed * (step + 1) * dt;
    input.rotation = pushed.rotation - turnRate * (step + 1) * dt;
    return input;
}

// An alpha loop formed by the mechanics, and its reduction. The redundant
// sigmoid takes the novice's insertion for 15 s; then the tip is hooked with
// the up/down dial at its stop and the shaft pushed on at 5 cm/s while it is
// turned counter-clockwise at 1 rad/s for 7 s, the way an alpha loop forms
// in a patient (a push with counter-clockwise torque). The shaft curls round
// in the sigmoid and carries the colon with it on its mesentery. Then the
// dial is released and the scope withdrawn at 5 cm/s while it is turned
// clockwise at 2 rad/s for 6 s (30 cm and almost two turns), the reduction
// the reference describes (withdrawal with clockwise torque, often more than
// a whole turn).
// Asserted: no loop is read after the novice's insertion; at the end of the
// push the detector reads an alpha loop in the sigmoid, from the shaft's
// shape (it turns a closed loop beyond the colon's path); the recording holds
// the alpha loop's formation, and its resolution during the withdrawal; the
// straightened scope reads no loop over the last 0.5 s.
// Measured: see the test's recorded properties (the turning at the end of
// the push, the excess shaft then, the times of the two events).
TEST(MechanicalLoops,
     APushWithCounterClockwiseTorqueFormsAnAlphaLoopAndWithdrawingWithClockwiseTorqueReducesIt)
{
    constexpr int kSettled = 500;      // last steps of the withdrawal in which no loop may be read
    constexpr double kTurnRate = 2.0;  // rad/s clockwise while withdrawing
    ProcedureLoop loop(looptest::redundantSigmoidColon(), ProcedureSettings{});
    const double dt = ProcedureSettings{}.stepping.loopStep;
    looptest::RunSummary summary;
    const double pushStart = kNovice * dt;
    const procedure::InputSample pushed = curlTheShaft(loop, summary);
    const procedure::LoopSignals atPush = loop.loops().signals();
    RecordProperty("turning_at_push_end_rad", std::to_string(atPush.turning));
    RecordProperty("excess_at_push_end_m", std::to_string(atPush.excessShaft));
    RecordProperty("tip_arc_at_push_end_m", std::to_string(atPush.tipArcLength));
    EXPECT_EQ(loopName(loop.loops().current()), loopName(LoopKind::Alpha))
        << "turning " << atPush.turning << " rad, excess " << atPush.excessShaft << " m";
    EXPECT_EQ(atPush.segment, geometry::Segment::Sigmoid);
    EXPECT_TRUE(atPush.closed);
    EXPECT_GT(atPush.turning, LoopDetector::kClosedTurning);
    const double formed = firstEvent(loop.recording(), EventKind::LoopFormed, "alpha", pushStart);
    RecordProperty("alpha_formed_s", std::to_string(formed));
    EXPECT_GE(formed, pushStart) << "the alpha loop formed during the push";

    const double withdrawStart = loop.time();
    int loopedAtTheEnd = 0;
    for (int s = 0; s < kWithdraw; ++s) {
        loop.step(withdrawal(pushed, s, kTurnRate, dt));
        looptest::observe(loop, summary);
        loopedAtTheEnd += s >= kWithdraw - kSettled && loop.loops().current() != LoopKind::None ? 1 : 0;
    }
    const double resolved = firstEvent(loop.recording(), EventKind::LoopResolved, "alpha", withdrawStart);
    RecordProperty("alpha_resolved_s", std::to_string(resolved));
    RecordProperty("turning_at_end_rad", std::to_string(loop.loops().signals().turning));
    EXPECT_GE(resolved, withdrawStart) << "the alpha loop resolved during the withdrawal";
    EXPECT_EQ(loopedAtTheEnd, 0) << "steps of the last 0.5 s with a loop read";
    EXPECT_EQ(loopName(loop.loops().current()), loopName(LoopKind::None))
        << "turning " << loop.loops().signals().turning << " rad, excess "
        << loop.loops().signals().excessShaft << " m";
    EXPECT_TRUE(summary.finite);
}

// The same withdrawal without torque does not reduce the loop: the alpha
// loop stays and the tip does not come back along the colon while 30 cm of
// shaft is pulled out. Measured: the tip moved 5.0 cm further in (the
// paradoxical advance of a looped scope being withdrawn), a pull of 11.8 N
// at most at the handle, the turning 5.78 rad at the end.
TEST(MechanicalLoops, WithdrawingTheAlphaLoopWithoutTorqueLeavesIt)
{
    constexpr double kTipHeld = 0.05;  // m the tip may travel back along the colon
    ProcedureLoop loop(looptest::redundantSigmoidColon(), ProcedureSettings{});
    const double dt = ProcedureSettings{}.stepping.loopStep;
    looptest::RunSummary summary;
    const procedure::InputSample pushed = curlTheShaft(loop, summary);
    ASSERT_EQ(loopName(loop.loops().current()), loopName(LoopKind::Alpha));
    const double tipBefore = loop.loops().signals().tipArcLength;
    double strongestPull = 0.0;  // N, the most negative handle force
    for (int s = 0; s < kWithdraw; ++s) {
        loop.step(withdrawal(pushed, s, 0.0, dt));
        looptest::observe(loop, summary);
        strongestPull = std::min(strongestPull, loop.outputs().handleForce);
    }
    const double tipTravel = tipBefore - loop.loops().signals().tipArcLength;
    RecordProperty("tip_travel_back_m", std::to_string(tipTravel));
    RecordProperty("strongest_pull_N", std::to_string(strongestPull));
    RecordProperty("turning_at_end_rad", std::to_string(loop.loops().signals().turning));
    EXPECT_EQ(loopName(loop.loops().current()), loopName(LoopKind::Alpha))
        << "turning " << loop.loops().signals().turning << " rad";
    EXPECT_LT(tipTravel, kTipHeld) << "m the tip went back while 30 cm of shaft came out";
    EXPECT_TRUE(summary.finite);
}

}  // namespace
