/// \file
/// `colonosim-hdc --device simulated --connect HOST:PORT [--duration S] [--hand push|replay:TRACE]
/// [--exit-on-disconnect] [--json]`:
/// the Haptic Device Controller, a separate process next to the device. Its servo loop runs at 1 kHz
/// whatever the simulator does: it sends the device's input to the simulator (`colonosim run --operator
/// hdc:PORT`) over OpenIGTLink and renders the handle force it gets back, through the safety chain of
/// simcore/devices/ForceServo.h. SIGINT or SIGTERM is an emergency stop: the force goes to zero at once.
/// At the end it prints the servo's period and jitter and the pose-to-force latency.

#include "simcore/devices/HdcController.h"
#include "simcore/procedure/InputTrace.h"
#include "trainer_ui/cli/CommandLine.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>

namespace {

using namespace colonosim;

std::atomic<bool> g_stop{false};

extern "C" void onSignal(int)
{
    g_stop = true;
}

/// Pushes in at 2 cm/s to 30 cm, sweeping the shaft +-0.5 rad at 0.2 Hz.
procedure::InputSample push(double t)
{
    procedure::InputSample s;
    s.insertion = std::min(0.3, 0.02 * t);
    s.rotation = 0.5 * std::sin(2.0 * 3.141592653589793 * 0.2 * t);
    return s;
}

int run(std::span<char* const> args)
{
    const cli::CommandLine line(args, {"--json", "--help", "--exit-on-disconnect"},
                                {"--device", "--connect", "--duration", "--hand"});
    if (line.has("--help")) {
        std::cout << "usage: colonosim-hdc --device simulated --connect HOST:PORT [--duration S]\n"
                     "                     [--hand push|replay:TRACE] [--exit-on-disconnect] [--json]\n"
                     "The Haptic Device Controller: a 1 kHz servo loop next to the device, linked to the\n"
                     "simulator (colonosim run --operator hdc:PORT) over OpenIGTLink.\n"
                     "  --device simulated   a mass-damper device held by a virtual hand (no hardware)\n"
                     "  --duration S         run for S seconds, 0.1-86400 (default 60)\n"
                     "  --hand push          the hand pushes in at 2 cm/s to 30 cm, twisting (default)\n"
                     "  --hand replay:TRACE  the hand follows a recorded input trace (session.trace)\n"
                     "  --exit-on-disconnect end when the simulator closes the link (after one was made)\n"
                     "SIGINT or SIGTERM is an emergency stop (force to zero at once), then exit.\n";
        return 0;
    }
    const std::optional<std::string> device = line.value("--device");
    const std::optional<std::string> connect = line.value("--connect");
    if (!device || !connect) {
        throw cli::UsageError("--device and --connect are required (see --help)");
    }
    if (*device != "simulated") {
        throw cli::UsageError("--device = \"" + *device +
                              "\" is not available (allowed: simulated; hardware drivers plug in behind "
                              "devices::HapticDevice)");
    }
    const size_t colon = connect->rfind(':');
    const std::string host = colon == std::string::npos ? std::string() : connect->substr(0, colon);
    const std::string portText = colon == std::string::npos ? std::string() : connect->substr(colon + 1);
    char* end = nullptr;
    const long port = std::strtol(portText.c_str(), &end, 10);
    if (host.empty() || portText.empty() || *end != '\0' || port < 1 || port > 65535) {
        throw cli::UsageError("--connect = \"" + *connect + "\" is not HOST:PORT with PORT in [1, 65535]");
    }
    const double duration = line.number("--duration", 60.0, 0.1, 86400.0, "s");
    devices::HandTrajectory hand = push;
    const std::string handName = line.value("--hand").value_or("push");
    if (handName.starts_with("replay:")) {
        auto trace = std::make_shared<procedure::InputTrace>(procedure::readTrace(handName.substr(7)));
        if (trace->samples.empty()) {
            throw cli::UsageError("--hand " + handName + ": the trace has no samples");
        }
        hand = [trace](double t) {
            const auto i = static_cast<size_t>(
                std::clamp(t / trace->loopStep, 0.0, static_cast<double>(trace->samples.size() - 1)));
            return trace->samples[i];
        };
    } else if (handName != "push") {
        throw cli::UsageError("--hand = \"" + handName + "\" is not one of push, replay:TRACE");
    }

    devices::SimulatedDevice simulated(hand);
    const devices::HapticParameters parameters;
    devices::HdcController hdc(simulated, parameters, host, static_cast<int>(port));
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::atomic<bool> done{false};
    std::jthread servo([&](std::stop_token stop) {
        hdc.run(stop, duration);
        done = true;
    });
    const bool exitOnDisconnect = line.has("--exit-on-disconnect");
    while (!done.load() && !g_stop.load()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        if (exitOnDisconnect && hdc.everConnected() && !hdc.linkUp()) {
            break;  // the session is over
        }
    }
    if (g_stop.load()) {
        hdc.requestEmergencyStop();  // the servo zeroes the force on its next tick
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::cerr << "colonosim-hdc: emergency stop\n";
    }
    servo.request_stop();
    servo.join();

    const devices::ServoStatistics& s = hdc.statistics();
    nlohmann::json out;
    out["ticks"] = s.ticks;
    out["servo_period_p50_ms"] = 1e3 * s.periods.quantile(0.5);
    out["servo_period_p99_ms"] = 1e3 * s.periods.quantile(0.99);
    out["servo_period_max_ms"] = 1e3 * s.periods.max();
    out["servo_jitter_p99_ms"] = 1e3 * s.jitter.quantile(0.99);
    out["servo_jitter_max_ms"] = 1e3 * s.jitter.max();
    out["loads_received"] = s.loadsReceived;
    out["latency_p50_ms"] = 1e3 * s.latencies.quantile(0.5);
    out["latency_p99_ms"] = 1e3 * s.latencies.quantile(0.99);
    out["latency_max_ms"] = 1e3 * s.latencies.max();
    // A load applies at the servo tick after it arrives, so latencies come in
    // whole ticks (plus the ticks' jitter): the share of loads that came a
    // tick late or more, which the p99 alone shows only as 1 or 2 ticks.
    out["latency_late_fraction"] = s.latencies.fractionAbove(1.5 * hdc.servo().parameters().servoPeriod);
    out["messages_refused"] = s.messagesRefused;
    out["connections"] = s.reconnects;
    out["max_force_step_N"] = s.maxOutputStep;
    out["final_state"] = devices::toString(hdc.servo().state());
    out["final_force_N"] = simulated.appliedForce();
    out["emergency_stop_from_N"] = s.stopFromForce;
    out["emergency_stop_to_N"] = s.stopToForce;
    out["last_refusal"] = hdc.lastRefusal();
    if (line.has("--json")) {
        std::cout << out.dump(2) << '\n';
    } else {
        for (const auto& [key, value] : out.items()) {
            std::cout << key << ": " << value << '\n';
        }
    }
    if (s.reconnects == 0) {
        std::cerr << "colonosim-hdc: never connected to " << *connect << '\n';
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        return run(std::span<char* const>(argv + 1, static_cast<size_t>(argc - 1)));
    } catch (const cli::UsageError& error) {
        std::cerr << "colonosim-hdc: " << error.what() << '\n';
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "colonosim-hdc: " << error.what() << '\n';
        return 1;
    }
}
