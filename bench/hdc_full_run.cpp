// The whole procedure through the Haptic Device Controller, as a person with
// a haptic device drives it, reported (the test
// HdcEndToEnd.TheSimulatedDeviceDrivesTheExpertsWholeProcedureToTheCecumAndBack
// asserts the same run ticked in lockstep): the scripted expert watches the
// procedure and moves the virtual hand of the simulated device; the HDC (its
// own thread, real time, 1 kHz) sends the device's input over OpenIGTLink on
// loopback; the simulator's HDC
// operator hands it to the procedure loop, which steps on each device frame
// as it arrives (never ahead of the device's clock) and sends the handle
// load back for the HDC's servo to render.
// The expert closes its loop through the device (its grip and carriage), not
// through the loop's input directly.
//
//   hdc_full_run [--seconds S] [--grip N_PER_M] [--twist-grip N_M_PER_RAD] [--lockstep 0|1]
//
// --lockstep 1 drives the HDC's servo ticks from this thread, one before each
// loop step, on the servo's own clock (tick k at k servo periods) instead of
// its real-time thread: the same device, link, messages and loop, in as much
// wall time as the computation takes (the loop never falls behind the
// device), and the same run each time.
//
// --grip and --twist-grip set the virtual hand's grip on the carriage and on
// the shaft (SimulatedDevice::Parameters; their damping follows, near
// critical). The defaults are a relaxed grip.
//
// Prints: time to the cecum (or "never"), simulated and wall time, steps with
// the tip more than a scope diameter into the wall (in all and per 10 s), the
// largest lag between the expert's hand and the input the loop got, the
// device frames used, the widest gap between recorded samples, and the
// servo's largest force step against its rate limit. Takes the simulated
// time in wall time at least (300 s by default).

#include "simcore/devices/HandTarget.h"
#include "simcore/devices/HdcController.h"
#include "simcore/devices/HdcOperator.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace colonosim;
using namespace colonosim::devices;

double option(int argc, char** argv, const std::string& name, double fallback, double lo, double hi)
{
    for (int i = 1; i + 1 < argc; ++i) {
        if (name == argv[i]) {
            char* end = nullptr;
            const double v = std::strtod(argv[i + 1], &end);
            if (end == argv[i + 1] || *end != '\0' || !(v >= lo && v <= hi)) {
                std::fprintf(stderr, "hdc_full_run: %s = %s is not a number in the allowed range [%g, %g]\n",
                             name.c_str(), argv[i + 1], lo, hi);
                std::exit(2);
            }
            return v;
        }
    }
    return fallback;
}

}  // namespace

int main(int argc, char** argv)
{
    const double seconds = option(argc, argv, "--seconds", 300.0, 1.0, 600.0);
    SimulatedDevice::Parameters grip;
    grip.handStiffness = option(argc, argv, "--grip", grip.handStiffness,
                                SimulatedDevice::Parameters::handStiffnessSpec.minValue,
                                SimulatedDevice::Parameters::handStiffnessSpec.maxValue);
    grip.handTorsionStiffness = option(argc, argv, "--twist-grip", grip.handTorsionStiffness,
                                       SimulatedDevice::Parameters::torsionStiffnessSpec.minValue,
                                       SimulatedDevice::Parameters::torsionStiffnessSpec.maxValue);
    // Near critical damping of the grip on the carriage and on the rotor, as the defaults'.
    grip.handDamping = std::min(SimulatedDevice::Parameters::handDampingSpec.maxValue,
                                2.0 * std::sqrt(grip.handStiffness * grip.carriageMass));
    grip.handTorsionDamping = std::min(SimulatedDevice::Parameters::torsionDampingSpec.maxValue,
                                       2.0 * std::sqrt(grip.handTorsionStiffness * grip.rotorInertia));

    const double lockstepFlag = option(argc, argv, "--lockstep", 0.0, 0.0, 1.0);
    if (lockstepFlag != 0.0 && lockstepFlag != 1.0) {
        std::fprintf(stderr, "hdc_full_run: --lockstep = %g must be 0 or 1\n", lockstepFlag);
        return 2;
    }
    const bool lockstep = lockstepFlag == 1.0;

    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureSettings settings;
    const HapticParameters parameters;
    procedure::ProcedureLoop loop(anatomy, settings);
    HdcOperator hdcInput(0, parameters);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    HandTarget hand;
    SimulatedDevice device([&hand](double) { return hand.latest(); }, grip);
    HdcController hdc(device, parameters, "127.0.0.1", hdcInput.server().port());
    std::jthread hdcThread;
    if (!lockstep) {
        hdcThread = std::jthread([&hdc](std::stop_token stop) { hdc.run(stop, 1e6); });
    }
    for (int i = 0; i < 4000 && !hdcInput.server().connected(); ++i) {
        if (lockstep) {
            hdc.tickLockstep();
        }
        std::this_thread::sleep_for(std::chrono::microseconds(500));  // the device's first frame
    }
    if (!hdcInput.server().connected()) {
        std::fprintf(stderr, "hdc_full_run: the HDC did not connect within 2 s\n");
        return 1;
    }

    const double dt = settings.stepping.loopStep;
    const double diameter = settings.scope.outerDiameter;
    const auto maxSteps = static_cast<long>(seconds / dt);
    long outside = 0;
    std::vector<long> outsideBy10s(static_cast<size_t>(std::ceil(seconds / 10.0)) + 1, 0);
    double largestLag = 0.0;      // m
    double largestTurnLag = 0.0;  // rad
    double largestDialLag = 0.0;  // rad
    double cecum = -1.0;
    long steps = 0;
    const auto start = std::chrono::steady_clock::now();
    for (; steps < maxSteps && !expert.finished(); ++steps) {
        // The HDC operator keeps time: the loop steps on each device frame.
        const procedure::InputSample wanted = expert.next(loop);
        hand.publish(wanted);
        if (lockstep) {
            hdc.tickLockstep();
        }
        hdcInput.recordConnection(loop);
        loop.step(hdcInput.next(loop), &hdcInput);
        if (!loop.lumen().contacts().empty() && loop.lumen().contacts().back().depth > diameter) {
            ++outside;
            ++outsideBy10s[static_cast<size_t>(loop.time() / 10.0)];
        }
        const procedure::InputSample& got = loop.lastFrame().input;
        largestLag = std::max(largestLag, std::abs(wanted.insertion - got.insertion));
        largestTurnLag = std::max(largestTurnLag, std::abs(wanted.rotation - got.rotation));
        largestDialLag = std::max({largestDialLag, std::abs(wanted.dialUpDown - got.dialUpDown),
                                   std::abs(wanted.dialLeftRight - got.dialLeftRight)});
        if (cecum < 0.0) {
            for (const auto& e : loop.recording().events) {
                cecum = e.kind == procedure::EventKind::CecumReached ? e.time : cecum;
            }
        }
    }
    if (hdcThread.joinable()) {
        hdcThread.request_stop();
        hdcThread.join();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const auto& samples = loop.recording().samples;
    double widestGap = 0.0;
    for (size_t k = 1; k < samples.size(); ++k) {
        widestGap = std::max(widestGap, samples[k].time - samples[k - 1].time);
    }
    std::printf(
        "%s; grip %.0f N/m, twist grip %.1f N m/rad; simulated %.3f s in %.1f s of wall time; expert %s\n",
        lockstep ? "servo ticked before each step (lockstep)" : "servo on its own real-time thread",
        grip.handStiffness, grip.handTorsionStiffness, loop.time(), wall,
        expert.finished() ? "finished" : "still at work");
    if (cecum >= 0.0) {
        std::printf("cecum reached at %.3f s\n", cecum);
    } else {
        std::printf("cecum never reached (tip %.3f m along the colon at the end)\n",
                    loop.lastFrame().tipArcLength);
    }
    std::printf("steps with the tip more than a scope diameter into the wall: %ld; per 10 s:", outside);
    for (const long n : outsideBy10s) {
        std::printf(" %ld", n);
    }
    std::printf(
        "\nlargest lag of the loop's input behind the expert's hand: insertion %.1f mm, rotation %.3f rad, "
        "dials %.3f rad\n",
        largestLag * 1e3, largestTurnLag, largestDialLag);
    std::printf("device frames used: %ld of %ld steps; widest gap between samples: %.4f s\n",
                hdcInput.framesUsed(), steps, widestGap);
    std::printf("servo: %d loads received, largest force step %.4f N per tick (limit %.4f)\n",
                hdc.statistics().loadsReceived, hdc.statistics().maxOutputStep,
                parameters.forceRateLimit * parameters.servoPeriod);
    return 0;
}
