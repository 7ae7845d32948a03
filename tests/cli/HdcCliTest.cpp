// The two processes of the haptic split as a person would start them:
// `colonosim run --operator hdc:PORT` waits for a device, `colonosim-hdc`
// connects with the simulated device; and their refusals of bad arguments.
#include "RunColonosim.h"

#include "simcore/devices/HdcServer.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace {

using colonosim::testing::runColonosim;

colonosim::testing::Result runHdc(const std::string& arguments)
{
    return colonosim::testing::runCommand(COLONOSIM_HDC_EXECUTABLE, arguments);
}

TEST(HdcCli, BadArgumentsAreRefusedNamingTheField)
{
    auto r = runHdc("--device phantom --connect 127.0.0.1:20000");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--device = \"phantom\""), std::string::npos) << r.output;
    r = runHdc("--device simulated --connect localhost");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("HOST:PORT"), std::string::npos) << r.output;
    r = runHdc("--device simulated --connect 127.0.0.1:20000 --duration 0");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--duration"), std::string::npos) << r.output;
    r = runColonosim("run --default --operator hdc:80 --out /nonexistent");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("port = \"80\" is outside [1024, 65535]"), std::string::npos) << r.output;
    r = runColonosim("run --default --operator gamepad:x --out /nonexistent");
    EXPECT_EQ(r.status, 2);
}

TEST(HdcCli, TheSimulatedDeviceDrivesASessionThroughTheHdcProcess)
{
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "colonosim-hdc-cli";
    std::filesystem::remove_all(out);
    const int port = 20000 + static_cast<int>(::getpid() % 20000);
    colonosim::testing::Result simulator;
    std::thread sim([&] {
        simulator = runColonosim("run --default --operator hdc:" + std::to_string(port) +
                                 " --max-time 2 --json --out " + out.string());
    });
    // The HDC retries until the simulator listens (building the colon takes a moment).
    const auto hdc = runHdc("--device simulated --connect 127.0.0.1:" + std::to_string(port) +
                            " --duration 120 --exit-on-disconnect --json");
    sim.join();
    ASSERT_EQ(simulator.status, 0) << simulator.output;
    ASSERT_EQ(hdc.status, 0) << hdc.output;
    const auto stats = nlohmann::json::parse(hdc.output.substr(hdc.output.find('{')));
    EXPECT_GE(stats["connections"].get<int>(), 1);
    EXPECT_GT(stats["loads_received"].get<int>(), 100);
    EXPECT_EQ(stats["messages_refused"].get<int>(), 0);
    EXPECT_LE(stats["max_force_step_N"].get<double>(), 5.0 + 1e-9);  // 5000 N/s over 1 ms
    std::ifstream events(out / "events.csv");
    std::stringstream text;
    text << events.rdbuf();
    EXPECT_NE(text.str().find("device_connected,simulated"), std::string::npos) << text.str();
}

// SIGINT to colonosim-hdc is an emergency stop. The test plays the simulator
// (an HdcServer answering every input frame with an 8 N load); the HDC ramps
// the force up at its rate limit (5 N a tick), and on the signal drops it to
// zero at once (from the whole 8 N to zero on the tick the stop latches, no
// ramp), tells the simulator (STATUS), and exits cleanly with its statistics.
TEST(HdcCli, SigintIsAnEmergencyStopThatDropsTheForceToZeroAtOnce)
{
    const colonosim::devices::HapticParameters parameters;
    colonosim::devices::HdcServer server(0, parameters);
    std::atomic<bool> exited{false};
    colonosim::testing::Result hdc;
    std::thread process([&] {
        // timeout sends SIGINT after 3 s; --preserve-status exits with the HDC's status.
        hdc = colonosim::testing::runCommand("timeout --preserve-status -s INT 3 " COLONOSIM_HDC_EXECUTABLE,
                                             "--device simulated --connect 127.0.0.1:" +
                                                 std::to_string(server.port()) + " --duration 60 --json");
        exited = true;
    });
    constexpr double kLoad = 8.0;  // N, resisting insertion
    int answered = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!exited.load() && std::chrono::steady_clock::now() < deadline) {
        if (const auto frame = server.waitForInput(0.01)) {
            server.publishLoad({kLoad, 0.0}, frame->time);
            ++answered;
        }
    }
    process.join();
    ASSERT_EQ(hdc.status, 0) << hdc.output;
    EXPECT_NE(hdc.output.find("colonosim-hdc: emergency stop"), std::string::npos) << hdc.output;
    EXPECT_GT(answered, 500) << "about 2 s of frames answered before the signal";
    EXPECT_TRUE(server.emergencyStop()) << "the HDC reported its emergency stop to the simulator";
    const auto stats = nlohmann::json::parse(hdc.output.substr(hdc.output.find('{')));
    EXPECT_EQ(stats["final_state"], "emergency stop");
    EXPECT_GT(stats["loads_received"].get<int>(), 500);
    EXPECT_EQ(stats["final_force_N"].get<double>(), 0.0);
    EXPECT_NEAR(stats["emergency_stop_from_N"].get<double>(), kLoad, 1e-6)
        << "the stop latched while the whole load was applied";
    EXPECT_EQ(stats["emergency_stop_to_N"].get<double>(), 0.0) << "and that same tick applied zero";
    EXPECT_LE(stats["max_force_step_N"].get<double>(), 5.0 + 1e-9) << "the ramp up: at most 5 N a tick";
}

}  // namespace
