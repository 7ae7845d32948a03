// The whole loop without hardware: a recorded expert trace moves the virtual
// hand of the simulated device; the HDC (its own thread, real time, 1 kHz)
// sends the device's input over OpenIGTLink to the simulator's HDC server;
// the procedure loop steps on it and sends the handle load back, which the
// HDC renders on the device. Midway the HDC process "dies" and a new one
// connects: the session's record goes on without a gap.
#include "simcore/devices/HdcController.h"
#include "simcore/devices/HdcServer.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace {

using namespace colonosim;
using namespace colonosim::devices;

TEST(HdcEndToEnd, TheSimulatedDeviceDrivesAnExpertRunThroughTheHdc)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureSettings settings;
    // The expert's hand, recorded.
    constexpr int kSteps = 1500;
    std::vector<procedure::InputSample> hand;
    size_t expertSamples = 0;
    {
        procedure::ProcedureLoop expert(anatomy, settings);
        procedure::ScriptedOperator op(procedure::expertStyle());
        for (int i = 0; i < kSteps; ++i) {
            const procedure::InputSample in = op.next(expert);
            hand.push_back(in);
            expert.step(in);
        }
        expertSamples = expert.recording().samples.size();
    }
    const double dt = settings.stepping.loopStep;
    // The HDC paces the hand by the simulator's progress, so the hand follows
    // the recorded expert whether the simulator keeps real time or falls
    // behind it (a loaded machine).
    std::atomic<double> simulatorTime{0.0};
    auto trajectory = [&](double) {
        const auto i = static_cast<size_t>(std::clamp(simulatorTime.load() / dt, 0.0, double(kSteps - 1)));
        return hand[i];
    };
    HapticParameters parameters;
    HdcServer server(0, parameters);
    procedure::ProcedureLoop loop(anatomy, settings);

    SimulatedDevice firstDevice(trajectory);
    HdcController first(firstDevice, parameters, "127.0.0.1", server.port());
    std::jthread firstThread([&](std::stop_token stop) { first.run(stop, 60.0); });

    procedure::InputSample input;
    double inputTime = 0.0;
    bool connected = false;
    int knownConnection = 0;
    long frames = 0;
    double largestLag = 0.0;
    std::unique_ptr<SimulatedDevice> secondDevice;
    std::unique_ptr<HdcController> second;
    std::jthread secondThread;
    // Like the trainer's loop, the simulator never runs ahead of the wall
    // clock: a device frame arrives each millisecond, one per loop step.
    const auto start = std::chrono::steady_clock::now();
    for (int step = 0; step < kSteps; ++step) {
        std::this_thread::sleep_until(start + std::chrono::duration<double>(step * dt));
        if (step == kSteps / 2) {
            firstThread.request_stop();  // the first HDC goes away mid-procedure
            firstThread.join();
            secondDevice = std::make_unique<SimulatedDevice>(trajectory);
            second = std::make_unique<HdcController>(*secondDevice, parameters, "127.0.0.1", server.port());
            secondThread = std::jthread([&](std::stop_token stop) { second->run(stop, 60.0); });
        }
        // As HdcOperator::recordConnection: a link replaced between two
        // steps is a disconnection and a connection (the server counts them).
        const bool now = server.connected();
        const int connection = server.connections();
        if (connected && connection != knownConnection) {
            connected = false;
            loop.noteDevice("simulated", false);
        }
        if (now != connected) {
            connected = now;
            knownConnection = connection;
            loop.noteDevice("simulated", connected);
        }
        if (step == 0 || step == kSteps / 2 + 1) {
            // Wait for the device's first frame on each connection.
            for (int i = 0; i < 4000 && !server.connected(); ++i) {
                std::this_thread::sleep_for(std::chrono::microseconds(500));
            }
        }
        if (std::optional<StampedInput> in = server.latestInput()) {
            input = in->input;
            inputTime = in->time;
            ++frames;
            EXPECT_STREQ(in->device, "simulated");
        }
        loop.step(input);
        simulatorTime = loop.time();
        largestLag =
            std::max(largestLag, std::abs(input.insertion - hand[static_cast<size_t>(step)].insertion));
        server.publishLoad(HandleCommand{loop.outputs().handleForce, loop.outputs().handleTorque}, inputTime);
    }
    secondThread.request_stop();
    secondThread.join();

    EXPECT_GT(frames, kSteps / 4);
    EXPECT_GE(server.connections(), 2);
    // The device followed the expert's hand: within the virtual hand's lag.
    EXPECT_LT(largestLag, 0.01);
    EXPECT_GT(loop.lastFrame().input.insertion, 0.03);
    int connects = 0, disconnects = 0;
    for (const auto& e : loop.recording().events) {
        connects += e.kind == procedure::EventKind::DeviceConnected && e.detail == "simulated" ? 1 : 0;
        disconnects += e.kind == procedure::EventKind::DeviceDisconnected ? 1 : 0;
    }
    EXPECT_GE(connects, 2);
    EXPECT_GE(disconnects, 1);
    // No sample was lost across the reconnection: 100 Hz over the whole run.
    EXPECT_EQ(loop.recording().samples.size(), expertSamples);
    for (const HdcController* hdc : {&first, second.get()}) {
        const ServoStatistics& s = hdc->statistics();
        EXPECT_GT(s.loadsReceived, 0);
        EXPECT_LE(s.maxOutputStep, parameters.forceRateLimit * parameters.servoPeriod + 1e-9);
        EXPECT_TRUE(std::isfinite(hdc->servo().output().force));
    }
}

}  // namespace
