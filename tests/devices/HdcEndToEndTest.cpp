// The whole loop without hardware, through the production path: the
// scripted expert watches the procedure and moves the virtual hand of the
// simulated device (it closes its loop through the device, as a person
// does); the HDC (its own thread, real time, 1 kHz) sends the device's input
// over OpenIGTLink to the simulator's HdcOperator, which steps the loop on
// each frame and sends the handle load back for the HDC to render. Midway
// the HDC process "dies" and a new one connects: the session's record goes
// on without a gap, and both connections are recorded with the device's name.
//
// The whole procedure the same way, anus to cecum and back, with the HDC's servo ticked
// from the test before each loop step on the servo's own clock instead of its
// real-time thread: the same device, OpenIGTLink link, server and loop, in
// the wall time the computation takes (in real time the loop falls behind the
// device past the sigmoid and the run would take over ten minutes of waiting).
#include "simcore/devices/HandTarget.h"
#include "simcore/devices/HdcController.h"
#include "simcore/devices/HdcOperator.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace {

using namespace colonosim;
using namespace colonosim::devices;

/// A firm grip on the carriage and the rotor (near critical damping), so the
/// device follows the hand within millimetres (bench/hdc_full_run --grip).
SimulatedDevice::Parameters firmGrip()
{
    SimulatedDevice::Parameters grip;
    grip.handStiffness = 5000.0;
    grip.handTorsionStiffness = 20.0;
    grip.handDamping = 2.0 * std::sqrt(grip.handStiffness * grip.carriageMass);
    grip.handTorsionDamping = 2.0 * std::sqrt(grip.handTorsionStiffness * grip.rotorInertia);
    return grip;
}

/// Waits up to 2 s for the device's first frame; `lockstep`: ticking it
/// meanwhile (no servo thread runs).
bool waitForConnection(const HdcOperator& hdc, HdcController* lockstep = nullptr)
{
    for (int i = 0; i < 4000 && !hdc.server().connected(); ++i) {
        if (lockstep != nullptr) {
            lockstep->tickLockstep();
        }
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    return hdc.server().connected();
}

/// The default colon's loop, the simulator's HDC operator on a free port and
/// the scripted expert with the hand it moves: what both tests drive.
class HdcEndToEnd : public ::testing::Test {
protected:
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureSettings settings;
    const HapticParameters parameters;
    procedure::ProcedureLoop loop{anatomy, settings};
    HdcOperator hdc{0, parameters};
    procedure::ScriptedOperator expert{procedure::expertStyle()};
    HandTarget hand;

    /// The simulated device's virtual hand: wherever the expert last put it.
    HandTrajectory followTheHand()
    {
        return [this](double) { return hand.latest(); };
    }
};

TEST_F(HdcEndToEnd, TheExpertDrivesTheLoopThroughTheSimulatedDeviceAndTheHdcAndSurvivesAReconnection)
{
    const SimulatedDevice::Parameters grip = firmGrip();

    SimulatedDevice firstDevice(followTheHand(), grip);
    auto first = std::make_unique<HdcController>(firstDevice, parameters, "127.0.0.1", hdc.server().port());
    std::jthread firstThread([&first](std::stop_token stop) { first->run(stop, 60.0); });
    ASSERT_TRUE(waitForConnection(hdc));

    constexpr int kSteps = 3000;
    std::unique_ptr<SimulatedDevice> secondDevice;
    std::unique_ptr<HdcController> second;
    std::jthread secondThread;
    double largestLag = 0.0;  // m, between the expert's hand and the loop's input while connected
    for (int step = 0; step < kSteps; ++step) {
        if (step == kSteps / 2) {
            firstThread.request_stop();  // the first HDC goes away mid-procedure
            firstThread.join();
            secondDevice = std::make_unique<SimulatedDevice>(followTheHand(), grip);
            second =
                std::make_unique<HdcController>(*secondDevice, parameters, "127.0.0.1", hdc.server().port());
            secondThread = std::jthread([&second](std::stop_token stop) { second->run(stop, 60.0); });
        }
        const procedure::InputSample wanted = expert.next(loop);
        hand.publish(wanted);
        hdc.recordConnection(loop);
        loop.step(hdc.next(loop), &hdc);
        if (hdc.server().connected() && step > 100) {
            largestLag = std::max(largestLag, std::abs(wanted.insertion - loop.lastFrame().input.insertion));
        }
    }
    secondThread.request_stop();
    secondThread.join();

    // The loop stepped on the device's frames (a silent spell around the
    // reconnection holds the last input).
    EXPECT_GT(hdc.framesUsed(), kSteps / 2);
    EXPECT_GE(hdc.server().connections(), 2);
    // The expert's hand reached the scope through the device, within the grip's lag.
    EXPECT_LT(largestLag, 0.01);
    EXPECT_GT(loop.lastFrame().input.insertion, 0.03);
    // Both connections are in the record with the device's name, and the break between them.
    int connects = 0;
    int disconnects = 0;
    for (const auto& e : loop.recording().events) {
        connects += e.kind == procedure::EventKind::DeviceConnected && e.detail == "simulated" ? 1 : 0;
        disconnects += e.kind == procedure::EventKind::DeviceDisconnected && e.detail == "simulated" ? 1 : 0;
    }
    EXPECT_GE(connects, 2);
    EXPECT_GE(disconnects, 1);
    EXPECT_EQ(connects, disconnects + 1) << "every connection after the first follows a recorded break";
    // No sample was lost across the reconnection: the first step's, then one every 10 ms.
    EXPECT_EQ(loop.recording().samples.size(), static_cast<size_t>(kSteps / 10 + 1));
    for (const HdcController* controller : {first.get(), second.get()}) {
        const ServoStatistics& s = controller->statistics();
        EXPECT_GT(s.loadsReceived, 0);
        EXPECT_LE(s.maxOutputStep, parameters.forceRateLimit * parameters.servoPeriod + 1e-9);
        EXPECT_TRUE(std::isfinite(controller->servo().output().force));
    }
}

TEST_F(HdcEndToEnd, TheSimulatedDeviceDrivesTheExpertsWholeProcedureToTheCecumAndBack)
{
    constexpr long kMaxSteps = 300000;  // 300 s at 1 kHz
    SimulatedDevice device(followTheHand(), firmGrip());
    HdcController controller(device, parameters, "127.0.0.1", hdc.server().port());
    ASSERT_TRUE(waitForConnection(hdc, &controller));

    const double diameter = settings.scope.outerDiameter;
    long steps = 0;
    long outside = 0;         // steps with the tip more than a scope diameter into the wall
    double largestLag = 0.0;  // m, between the expert's hand and the loop's input
    double cecum = -1.0;      // s
    for (; steps < kMaxSteps && !expert.finished(); ++steps) {
        const procedure::InputSample wanted = expert.next(loop);
        hand.publish(wanted);
        controller.tickLockstep();  // reads the device, sends its frame, takes the last load
        hdc.recordConnection(loop);
        loop.step(hdc.next(loop), &hdc);
        outside += loop.lumen().contacts().back().depth > diameter ? 1 : 0;
        largestLag = std::max(largestLag, std::abs(wanted.insertion - loop.lastFrame().input.insertion));
        if (cecum < 0.0 && loop.cecumReached()) {
            cecum = loop.time();
        }
    }
    const ServoStatistics& servo = controller.statistics();
    RecordProperty("cecum_s", std::to_string(cecum));
    RecordProperty("end_s", std::to_string(loop.time()));
    RecordProperty("steps_outside", std::to_string(outside));
    RecordProperty("largest_lag_mm", std::to_string(largestLag * 1e3));
    RecordProperty("frames_used", std::to_string(hdc.framesUsed()));
    RecordProperty("loads_received", std::to_string(servo.loadsReceived));

    // The expert reached the cecum and came back out, through the device alone.
    EXPECT_GT(cecum, 0.0) << "the tip is at " << loop.lastFrame().tipArcLength << " m";
    EXPECT_TRUE(expert.finished()) << "still at work after " << loop.time() << " s";
    // It stops 5 cm in (ScriptedOperator); the device follows within the grip's lag (1 cm below).
    EXPECT_LT(loop.lastFrame().input.insertion, 0.06) << "m of insertion at the end";
    // The loop stepped on the device's frames and the servo got the loads back. A frame that
    // has not arrived within HdcOperator::kFrameWait leaves the last input held for a step (30
    // of 267,841 steps in the run measured; a thread not scheduled in time), so not every step.
    EXPECT_GE(hdc.framesUsed(), steps - steps / 1000);
    EXPECT_GE(servo.loadsReceived, steps - steps / 1000);
    // The hand reached the scope within the grip's lag, and the servo's force stayed within its limits.
    EXPECT_LT(largestLag, 0.01);
    EXPECT_LE(servo.maxOutputStep, parameters.forceRateLimit * parameters.servoPeriod + 1e-9);
    EXPECT_TRUE(std::isfinite(controller.servo().output().force));
    // No sample lost: the first step's, then one every 10 ms.
    EXPECT_EQ(loop.recording().samples.size(), static_cast<size_t>(steps / 10 + 1));
    // The tip stayed inside the lumen but for a thousandth of the run at most (14 steps of
    // 267,841 in the run measured, all 40-50 s in; the direct run, without the device, has 8).
    EXPECT_LT(outside, steps / 1000) << "steps with the tip more than a scope diameter into the wall";
    // The session records the device that drove it.
    const auto& events = loop.recording().events;
    EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const procedure::RecordedEvent& e) {
        return e.kind == procedure::EventKind::DeviceConnected && e.detail == "simulated";
    }));
}

}  // namespace
