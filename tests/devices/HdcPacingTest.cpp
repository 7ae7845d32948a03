// The HDC keeps the session's time: the procedure loop steps on each device
// frame as it arrives, and never runs ahead of the person's hand, whatever
// its own step costs; with no device connected it steps on the wall clock.
// (A loop that ran as fast as it could would play the hand in slow motion:
// 12 s of a session done in 2 s of the hand's time.)
#include "simcore/devices/HdcController.h"
#include "simcore/devices/HdcOperator.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace {

using namespace colonosim;
using namespace colonosim::devices;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

const geometry::ColonAnatomy& defaultColon()
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return anatomy;
}

TEST(HdcPacing, TheLoopStepsOnEachDeviceFrameAndNeverRunsAheadOfTheHand)
{
    const HapticParameters parameters;
    HdcOperator hdc(0, parameters);
    procedure::ProcedureLoop loop(defaultColon(), procedure::ProcedureSettings{});
    // The hand pushes in at 2 cm/s from the moment the device starts.
    constexpr double kHandSpeed = 0.02;  // m/s
    SimulatedDevice device([](double t) {
        procedure::InputSample in;
        in.insertion = kHandSpeed * t;
        return in;
    });
    HdcController controller(device, parameters, "127.0.0.1", hdc.server().port());
    std::jthread servo([&controller](std::stop_token stop) { controller.run(stop, 60.0); });
    for (int i = 0; i < 4000 && !hdc.server().connected(); ++i) {
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    ASSERT_TRUE(hdc.server().connected());

    constexpr int kSteps = 1500;
    const Clock::time_point start = Clock::now();
    const double simulatedAtStart = loop.time();
    const long framesAtStart = hdc.framesUsed();
    double mostAhead = -1e9;  // s: simulated time minus wall time since the start
    for (int s = 0; s < kSteps; ++s) {
        hdc.recordConnection(loop);
        loop.step(hdc.next(loop), &hdc);
        mostAhead = std::max(mostAhead, (loop.time() - simulatedAtStart) - secondsSince(start));
    }
    const double wall = secondsSince(start);
    servo.request_stop();
    servo.join();

    // Never ahead of the hand: at most the one step a frame already waiting
    // lets it take early (an unpaced loop is seconds ahead after 1.5 s).
    EXPECT_LT(mostAhead, 0.01) << "simulated " << loop.time() - simulatedAtStart << " s in " << wall
                               << " s of wall time";
    // Steps on the device's frames: most steps take a frame of their own (a
    // silent device for kFrameWait lets a step hold the last one).
    EXPECT_GT(hdc.framesUsed() - framesAtStart, kSteps / 2);
    // The hand's motion reaches the scope at the hand's own speed: after
    // 1.5 s of its time the scope is in by about 3 cm, less the device's lag.
    EXPECT_GT(loop.lastFrame().input.insertion, 0.5 * kHandSpeed * (loop.time() - simulatedAtStart));
    // Every load went back: the HDC rendered the loop's answers.
    EXPECT_GT(controller.statistics().loadsReceived, kSteps / 2);
}

TEST(HdcPacing, WithNoDeviceTheLoopStepsOnTheWallClock)
{
    HdcOperator hdc(0, HapticParameters{});
    procedure::ProcedureLoop loop(defaultColon(), procedure::ProcedureSettings{});
    constexpr int kSteps = 300;
    const Clock::time_point start = Clock::now();
    for (int s = 0; s < kSteps; ++s) {
        hdc.recordConnection(loop);
        loop.step(hdc.next(loop), &hdc);
    }
    // The held scope's session still takes its real time: 300 steps of 1 ms
    // take at least 299 ms (the first step starts the schedule).
    EXPECT_GE(secondsSince(start), (kSteps - 1) * loop.trace().loopStep - 1e-4);
    EXPECT_EQ(hdc.framesUsed(), 0);
    EXPECT_DOUBLE_EQ(loop.lastFrame().input.insertion, 0.0);
}

// A host that passes the operator to step() as its HandleLoadSink has each
// step's load sent within the step (the device is answered before the
// colon's substeps); one that does not has it sent when it next asks for
// input. Either way each step's load goes out once.
TEST(HdcPacing, TheLoadGoesOutWithinTheStepWhenTheHostPassesTheSinkAndOnceEitherWay)
{
    HdcOperator early(0, HapticParameters{});
    HdcOperator late(0, HapticParameters{});
    procedure::ProcedureLoop earlyLoop(defaultColon(), procedure::ProcedureSettings{});
    procedure::ProcedureLoop lateLoop(defaultColon(), procedure::ProcedureSettings{});
    for (long s = 1; s <= 100; ++s) {
        earlyLoop.step(early.next(earlyLoop), &early);
        lateLoop.step(late.next(lateLoop));
        EXPECT_EQ(early.server().loadsPublished(), s) << "sent within step " << s;
        EXPECT_EQ(late.server().loadsPublished(), s - 1) << "sent when step " << s + 1 << " asks for input";
    }
    (void)early.next(earlyLoop);
    (void)late.next(lateLoop);
    EXPECT_EQ(early.server().loadsPublished(), 100) << "not sent twice";
    EXPECT_EQ(late.server().loadsPublished(), 100);
}

}  // namespace
