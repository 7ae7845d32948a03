// `colonosim rod` as a script uses it: JSON with the documented keys, the
// analytic cantilever solutions reproduced, and exit status 2 with field,
// value and range on bad input.

#include "RunColonosim.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace {

using colonosim::testing::Result;

Result run(const std::string& arguments, bool stdoutOnly = false)
{
    return colonosim::testing::runColonosim(arguments, stdoutOnly);
}

nlohmann::json rod(const std::string& arguments)
{
    const Result r = run("rod " + arguments + " --json", true);
    EXPECT_EQ(r.status, 0) << arguments;
    return nlohmann::json::parse(r.output);
}

TEST(RodCli, OutputsTheDocumentedKeys)
{
    const nlohmann::json out = rod("--length 1 --ei 0.033 --tip-load 0.01 --elements 79 --solver chain");
    for (const char* key : {"tip_x_m", "tip_y_m", "tip_angle_rad", "iterations", "time_us"}) {
        EXPECT_TRUE(out.contains(key)) << key;
    }
    EXPECT_EQ(out["iterations"].get<int>(), 50);
}

// Both solvers on the reference solutions (physical-parameters.md); the
// tolerances are those of tests/scope: 0.1% small deflection, 1% elastica.
TEST(RodCli, ReproducesTheReferenceSolutions)
{
    for (const char* solver : {"chain", "reference"}) {
        const std::string s = std::string(" --elements 79 --solver ") + solver;
        const nlohmann::json small = rod("--length 2 --ei 0.04 --tip-load 1e-6" + s);
        const double v = 1e-6 * 8.0 / (3.0 * 0.04);
        EXPECT_NEAR(-small["tip_y_m"].get<double>(), v, 1e-3 * v) << solver;
        const nlohmann::json elastica = rod("--length 1 --ei 0.033 --tip-load 0.066 --iterations 100" + s);
        EXPECT_NEAR(-elastica["tip_y_m"].get<double>(), 0.49346, 0.01 * 0.49346) << solver;
        EXPECT_NEAR(1.0 - elastica["tip_x_m"].get<double>(), 0.16064, 0.01 * 0.16064) << solver;
        const nlohmann::json arc = rod("--length 1 --ei 0.033 --end-moment 0.0495" + s);  // t = 1.5
        EXPECT_NEAR(arc["tip_angle_rad"].get<double>(), 1.5, 1e-9) << solver;
        // Distributed load, small deflection: v = q L^4 / (8 EI).
        const nlohmann::json uniform = rod("--length 1 --ei 0.033 --distributed-load 1e-5" + s);
        const double vq = 1e-5 / (8.0 * 0.033);
        EXPECT_NEAR(-uniform["tip_y_m"].get<double>(), vq, 2e-3 * vq) << solver;
    }
}

TEST(RodCli, BadInputExitsTwoNamingOptionValueAndRange)
{
    struct Case {
        const char* arguments;
        const char* expected;
    };
    for (const Case c : {Case{"--length nan --elements 10 --solver chain --json", "--length"},
                         Case{"--length 1 --ei -1 --elements 10 --solver chain --json", "[1e-06, 1e+06]"},
                         Case{"--elements 0 --solver chain --json", "--elements"},
                         Case{"--elements 2.5 --solver chain --json", "whole number"},
                         Case{"--elements 10 --solver magic --json", "chain, reference"},
                         Case{"--tip-load 1e300 --elements 10 --solver chain --json", "--tip-load"}}) {
        const Result r = run(std::string("rod ") + c.arguments);
        EXPECT_EQ(r.status, 2) << c.arguments;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.arguments << ": " << r.output;
    }
    EXPECT_EQ(run("rod --help").status, 0);
}

}  // namespace
