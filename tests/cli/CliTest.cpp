// The `colonosim` executable as a person or a script uses it: exit status 0
// on success and 2 on bad input, messages that name the field, the value and
// the allowed range, and machine-readable JSON.

#include "simcore/geometry/MeshExport.h"
#include "simcore/geometry/ProceduralColon.h"

#include "RunColonosim.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>

namespace {

using colonosim::testing::Result;

Result run(const std::string& arguments, bool stdoutOnly = false)
{
    return colonosim::testing::runColonosim(arguments, stdoutOnly);
}

std::filesystem::path tempDir()
{
    std::random_device device;
    const auto dir = std::filesystem::temp_directory_path() / ("colonosim_cli_" + std::to_string(device()));
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(Cli, HelpExitsZero)
{
    const Result r = run("--help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("demo"), std::string::npos);
    for (const char* sub : {"demo --help", "params --help", "mesh --help", "bench --help"}) {
        EXPECT_EQ(run(sub).status, 0) << sub;
    }
}

TEST(Cli, UnknownSubcommandAndOptionExitTwo)
{
    EXPECT_EQ(run("fly").status, 2);
    const Result r = run("demo --tissue --speed 3");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--speed"), std::string::npos) << r.output;
}

TEST(Cli, OutOfRangeNumberNamesOptionValueAndRange)
{
    for (const char* bad : {"--duration -1", "--duration abc", "--duration nan", "--duration 1e9"}) {
        const Result r = run(std::string("demo --tissue ") + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.output.find("--duration"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("[0.05, 60] s"), std::string::npos) << r.output;
    }
}

TEST(Cli, UnknownIntegratorIsRefusedWithTheAllowedNames)
{
    const Result r = run("demo --tissue --integrator verlet");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("verlet"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("symplectic_euler"), std::string::npos) << r.output;
}

TEST(Cli, WithoutADisplayTheWindowIsRefused)
{
    // (That no subcommand runs the headless demonstration is checked in DemoCliTest: it takes a while.)
    const std::string noDisplay =
        std::string("env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM ") + COLONOSIM_EXECUTABLE;
    const Result window = colonosim::testing::runCommand(noDisplay, "gui");
    EXPECT_EQ(window.status, 2) << window.output;
    EXPECT_NE(window.output.find("needs a display"), std::string::npos) << window.output;
}

TEST(Cli, DemoRunsAndReportsJson)
{
    const Result r = run("demo --tissue --duration 0.06 --json", true);
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json summary = nlohmann::json::parse(r.output);
    EXPECT_GE(summary["physics_nodes"].get<int>(), 1800);
    EXPECT_GE(summary["visual_vertices"].get<int>(), 50000);
    EXPECT_EQ(summary["rejected_steps"].get<int>(), 0);
    EXPECT_GT(summary["push_displacement_m"].get<double>(), 0.0);
    EXPECT_LT(summary["max_displacement_m"].get<double>(), 0.1);
}

// The run's summary for a person: each figure rounded to what it means
// (a simulated time to the millisecond, times to 10 ms, newtons and the
// discomfort scale to a tenth), not every binary digit of a sum of steps;
// the --json summary keeps every digit.
TEST(Cli, RunSummaryPrintsRoundedFigures)
{
    const std::filesystem::path dir = tempDir();
    const Result r =
        run("run --default --operator novice --max-time 1 --out " + (dir / "run").string(), true);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("procedure: 1.000 s simulated, operator novice\n"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("time to cecum: not reached\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("loops: {}, looped 0.00 s\n"), std::string::npos) << r.output;
    const std::size_t force = r.output.find("peak handle force: ");
    ASSERT_NE(force, std::string::npos) << r.output;
    std::istringstream line(r.output.substr(force + 19));
    std::string newtons;
    std::string unit;
    line >> newtons >> unit;
    EXPECT_EQ(unit, "N;") << r.output;
    const std::size_t point = newtons.find('.');
    ASSERT_NE(point, std::string::npos) << newtons;
    EXPECT_EQ(newtons.size() - point, 2U) << "one decimal: " << newtons;
    EXPECT_NE(r.output.find(" / 10\n"), std::string::npos) << r.output;
    std::filesystem::remove_all(dir);
}

// The run's summary gives the renderer's % mucosa visualised overall and by
// segment: 2 s of the expert see part of the rectum, none of the cecum, and
// the overall figure is the segments' weighted by their wall.
TEST(Cli, RunJsonGivesTheMucosaSeenOverallAndBySegment)
{
    const std::filesystem::path dir = tempDir();
    const Result r =
        run("run --default --operator expert --max-time 2 --json --out " + (dir / "run").string(), true);
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json summary = nlohmann::json::parse(r.output);
    ASSERT_TRUE(summary["mucosa_visualised"].is_number()) << r.output;
    const double overall = summary["mucosa_visualised"].get<double>();
    const nlohmann::json& bySegment = summary["mucosa_visualised_by_segment"];
    ASSERT_EQ(bySegment.size(), static_cast<size_t>(colonosim::geometry::kNumSegments)) << r.output;
    EXPECT_GT(bySegment["rectum"].get<double>(), overall) << "only the rectum is seen so far";
    EXPECT_LE(bySegment["rectum"].get<double>(), 1.0);
    EXPECT_EQ(bySegment["cecum"].get<double>(), 0.0);
    EXPECT_GT(overall, 0.0);
    std::filesystem::remove_all(dir);
}

TEST(Cli, ParameterDocumentationIsUpToDate)
{
    const Result r = run("params --markdown");
    ASSERT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("`tissue.wallYoungModulus` | Pa | 1.74e+06"), std::string::npos) << r.output;
    std::ifstream file(std::string(COLONOSIM_SOURCE_DIR) + "/docs/parameters.md");
    std::stringstream committed;
    committed << file.rdbuf();
    EXPECT_EQ(committed.str(), r.output)
        << "regenerate docs/parameters.md with `colonosim params --markdown`";
}

TEST(Cli, MeshInspectReadsAGoodFileAndRefusesBadOnes)
{
    const auto dir = tempDir();
    const auto anatomy = colonosim::geometry::buildProceduralColon(colonosim::geometry::AnatomyParameters{});
    const auto good = dir / "colon.stl";
    colonosim::geometry::writeStl(good, anatomy.physicsMesh, colonosim::geometry::MeshEncoding::Binary);
    const Result ok = run("mesh inspect " + good.string() + " --json");
    ASSERT_EQ(ok.status, 0) << ok.output;
    const nlohmann::json report = nlohmann::json::parse(ok.output);
    EXPECT_EQ(report["triangles"].get<int>(), anatomy.physicsMesh.numTriangles());

    const Result missing = run("mesh inspect " + (dir / "absent.obj").string());
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.output.find("absent.obj"), std::string::npos) << missing.output;

    const auto junk = dir / "junk.ply";
    std::ofstream(junk) << "this is not a mesh\n";
    const Result bad = run("mesh inspect " + junk.string());
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.output.find("junk.ply"), std::string::npos) << bad.output;
    std::filesystem::remove_all(dir);
}

}  // namespace
