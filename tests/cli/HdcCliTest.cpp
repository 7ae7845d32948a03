// The two processes of the haptic split as a person would start them:
// `colonosim run --operator hdc:PORT` waits for a device, `colonosim-hdc`
// connects with the simulated device; and their refusals of bad arguments.
#include "RunColonosim.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

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

}  // namespace
