// Runs the bench report at its quick scale into a temporary directory and
// checks its outputs: the files exist, the CSV has one row per integrator and
// step, summary.json has the required keys with finite positive figures, and
// the stable rows of RK4 and symplectic Euler converge as the step shrinks.

#include "bench/report/BenchReport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

struct CsvRow {
    std::string integrator;
    double step = 0.0;
    int stable = 0;
    double cpu = 0.0;
    double rms = 0.0;
    double max = 0.0;
};

std::vector<CsvRow> readCsv(const std::filesystem::path& path, std::string& header)
{
    std::ifstream in(path);
    std::getline(in, header);
    std::vector<CsvRow> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        CsvRow row;
        std::string rms;
        std::string max;
        fields >> row.integrator >> row.step >> row.stable >> row.cpu >> rms >> max;
        row.rms = rms == "NaN" ? NAN : std::stod(rms);
        row.max = max == "NaN" ? NAN : std::stod(max);
        rows.push_back(row);
    }
    return rows;
}

bool finitePositive(const nlohmann::json& value)
{
    return value.is_number() && std::isfinite(value.get<double>()) && value.get<double>() > 0.0;
}

/// Runs once per process; each check below reads its outputs.
struct QuickReport {
    std::filesystem::path s_dir;
    int s_status = -1;
    std::string s_log;
};

void checkWritesTheThreeFiles(const QuickReport& r)
{
    ASSERT_EQ(r.s_status, 0) << r.s_log;
    for (const char* name : {"speed_vs_error.csv", "speed_vs_error.svg", "summary.json"}) {
        EXPECT_GT(std::filesystem::file_size(r.s_dir / name), 100u) << name;
    }
}

void checkCsvHasFiveStepsPerIntegrator(const QuickReport& r)
{
    std::string header;
    const std::vector<CsvRow> rows = readCsv(r.s_dir / "speed_vs_error.csv", header);
    EXPECT_EQ(header, "integrator,step_s,stable,cpu_s_per_simulated_s,rms_error_m,max_error_m");
    std::map<std::string, int> count;
    for (const CsvRow& row : rows) {
        ++count[row.integrator];
        EXPECT_GT(row.step, 0.0);
        EXPECT_GT(row.cpu, 0.0);
        EXPECT_EQ(row.stable == 1, std::isfinite(row.rms)) << row.integrator << " " << row.step;
    }
    const std::map<std::string, int> expected{
        {"explicit_euler", 5}, {"symplectic_euler", 5}, {"rk4", 5}, {"backward_euler", 5}};
    EXPECT_EQ(count, expected);
}

void checkStableRowsConvergeForRk4AndSymplecticEuler(const QuickReport& r)
{
    std::string header;
    const std::vector<CsvRow> rows = readCsv(r.s_dir / "speed_vs_error.csv", header);
    for (const std::string name : {"rk4", "symplectic_euler"}) {
        std::map<double, double> errorByStep;  // ascending step
        for (const CsvRow& row : rows) {
            if (row.integrator == name && row.stable == 1) {
                errorByStep[row.step] = row.rms;
            }
        }
        ASSERT_GE(errorByStep.size(), 4u) << name;
        double previous = 0.0;
        for (const auto& [step, error] : errorByStep) {
            EXPECT_GT(error, previous) << name << ": error must grow with the step (h = " << step << ")";
            previous = error;
        }
    }
}

void checkSummaryHasRequiredFiniteFigures(const QuickReport& r)
{
    std::ifstream in(r.s_dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    ASSERT_TRUE(summary.is_object());
    for (const char* name : {"explicit_euler", "symplectic_euler", "rk4", "backward_euler"}) {
        EXPECT_TRUE(finitePositive(summary["colon_step_hz"][name])) << name;
    }
    EXPECT_TRUE(finitePositive(summary["mapping_54k_ms"]));
    EXPECT_TRUE(finitePositive(summary["reference_self_error_m"]));
    EXPECT_GT(summary["nodes"].get<int>(), 1000);
    EXPECT_GT(summary["visual_vertices"].get<int>(), 50000);
    EXPECT_TRUE(summary["quick"].get<bool>());
    EXPECT_TRUE(summary["machine"].is_object());
    const nlohmann::json& peer = summary["peer"];
    EXPECT_EQ(peer["name"], "bullet_btSoftBody");
    for (const char* key : {"colon_step_hz", "rms_error_m", "max_error_m"}) {
        EXPECT_TRUE(finitePositive(peer[key])) << key;
    }
    EXPECT_FALSE(peer["matching"].get<std::string>().empty());
    const nlohmann::json& active = summary["active_region"];
    for (const char* key : {"speedup", "awake_fraction"}) {
        EXPECT_TRUE(finitePositive(active[key])) << key;
    }
    for (const char* key : {"rms_error_m", "max_error_m"}) {
        EXPECT_TRUE(active[key].is_number() && active[key].get<double>() >= 0.0) << key;
    }
    EXPECT_LE(active["awake_fraction"].get<double>(), 1.0);
}

// One test (one report run, about 30-60 s): ctest runs each discovered test
// in its own process, so separate tests would each rerun the report.
TEST(BenchReport, QuickRunWritesConvergentCsvAndCompleteSummary)
{
    QuickReport r;
    r.s_dir = std::filesystem::temp_directory_path() /
              ("colonosim_bench_report_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(r.s_dir);
    std::ostringstream log;
    r.s_status = colonosim::bench::runBenchReport({true, r.s_dir}, log);
    r.s_log = log.str();
    {
        SCOPED_TRACE("WritesTheThreeFiles");
        checkWritesTheThreeFiles(r);
    }
    {
        SCOPED_TRACE("CsvHasFiveStepsPerIntegrator");
        checkCsvHasFiveStepsPerIntegrator(r);
    }
    {
        SCOPED_TRACE("StableRowsConvergeForRk4AndSymplecticEuler");
        checkStableRowsConvergeForRk4AndSymplecticEuler(r);
    }
    {
        SCOPED_TRACE("SummaryHasRequiredFiniteFigures");
        checkSummaryHasRequiredFiniteFigures(r);
    }
    std::filesystem::remove_all(r.s_dir);
}

}  // namespace
