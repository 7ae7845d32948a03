// `colonosim case` as a person or a script runs it: exit codes, messages
// naming the option, value and range, file:line errors, JSON.

#include "RunColonosim.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

using colonosim::testing::runColonosim;

class CaseCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir = std::filesystem::temp_directory_path() /
                ("colonosim-case-cli-" + std::to_string(::getpid()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }

    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    static std::string read(const std::string& file)
    {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    std::filesystem::path m_dir;
};

TEST_F(CaseCli, GenerateWritesAValidCaseAndRepeatsItByteForByte)
{
    const auto first = runColonosim("case generate --seed 31 --out " + path("a.xml"));
    EXPECT_EQ(first.status, 0) << first.output;
    EXPECT_NE(first.output.find("wrote"), std::string::npos);
    const auto second = runColonosim("case generate --seed 31 --out " + path("b.xml"));
    EXPECT_EQ(second.status, 0);
    EXPECT_FALSE(read(path("a.xml")).empty());
    EXPECT_EQ(read(path("a.xml")), read(path("b.xml")));
    const auto valid = runColonosim("case validate " + path("a.xml") + " " + path("b.xml"));
    EXPECT_EQ(valid.status, 0) << valid.output;
    EXPECT_NE(valid.output.find("a.xml: valid"), std::string::npos);
}

// A colon laid out through itself (generated seed 24 and the stored
// generator-1.0 seed 7, about one case in 20) is named with where it
// overlaps; the case stays valid and the exit status 0.
TEST_F(CaseCli, AColonThatPassesThroughItselfIsNamedWhereItOverlaps)
{
    const std::string stored =
        std::string(COLONOSIM_SOURCE_DIR) + "/tests/procedure/data/colon-through-itself.xml";
    const std::string golden =
        std::string(COLONOSIM_SOURCE_DIR) + "/tests/case_generator/golden/case-seed-2024.xml";
    const auto valid = runColonosim("case validate " + stored + " " + golden);
    EXPECT_EQ(valid.status, 0) << valid.output;
    EXPECT_NE(
        valid.output.find("passes through itself: the lumen at 0.385 m and at 1.165 m along it overlap by "
                          "36.3 mm"),
        std::string::npos)
        << valid.output;
    EXPECT_EQ(valid.output.find("through itself", valid.output.find("case-seed-2024.xml")), std::string::npos)
        << "the golden case's colon does not";

    const auto generated = runColonosim("case generate --seed 24 --out " + path("through.xml"));
    EXPECT_EQ(generated.status, 0) << generated.output;
    EXPECT_NE(generated.output.find("passes through itself"), std::string::npos) << generated.output;
    const auto plain = runColonosim("case generate --seed 1 --out " + path("plain.xml"));
    EXPECT_EQ(plain.output.find("through itself"), std::string::npos) << plain.output;
}

// Generated patient 7's colon (about 1.80 m) is longer than the scope: the
// simulated colon pleats onto the shaft by a few centimetres only, so its
// cecum is out of reach, and generating or validating it says so.
TEST_F(CaseCli, ACaseWhoseCecumIsBeyondTheScopeSaysSo)
{
    const std::string reach =
        "longer than the scope's 1.70 m working length; the simulated colon pleats onto "
        "the shaft by a few centimetres only, so its cecum is out of the scope's reach";
    const auto far = runColonosim("case generate --seed 7 --out " + path("far.xml"));
    ASSERT_EQ(far.status, 0) << far.output;
    EXPECT_NE(far.output.find("note: the colon is 1."), std::string::npos) << far.output;
    EXPECT_NE(far.output.find(reach), std::string::npos) << far.output;
    const auto valid = runColonosim("case validate " + path("far.xml"));
    EXPECT_EQ(valid.status, 0) << valid.output;
    EXPECT_NE(valid.output.find(reach), std::string::npos) << valid.output;
    const auto near = runColonosim("case generate --seed 1 --out " + path("near.xml"));
    ASSERT_EQ(near.status, 0) << near.output;
    EXPECT_EQ(near.output.find("out of the scope's reach"), std::string::npos) << near.output;
}

TEST_F(CaseCli, ConstraintsReachTheCase)
{
    const auto result = runColonosim("case generate --seed 5 --sex F --age-min 60 --age-max 65 --bmi-max 22 "
                                     "--require \"redundant_sigmoid and boston<=8\" --difficulty 3-5 --out " +
                                     path("c.xml"));
    ASSERT_EQ(result.status, 0) << result.output;
    const std::string text = read(path("c.xml"));
    EXPECT_NE(text.find("<sex>F</sex>"), std::string::npos);
    EXPECT_NE(text.find("<constraints>sex=F; age_min=60; age_max=65; bmi_max=22; difficulty=3-5; "
                        "require=redundant_sigmoid and boston&lt;=8</constraints>"),
              std::string::npos)
        << text.substr(0, 600);
}

TEST_F(CaseCli, BadArgumentsNameOptionValueAndRange)
{
    struct Bad {
        std::string args;
        std::string message;
    };
    for (const Bad& bad : {
             Bad{"case generate --seed -1 --out x.xml",
                 "--seed = -1 is not a whole number in the allowed range"},
             Bad{"case generate --seed 1 --sex X --out x.xml", "--sex = X is not one of: F, M"},
             Bad{"case generate --seed 1 --age-min 5 --out x.xml",
                 "--age-min = 5 is not a number in the allowed range [18, 110]"},
             Bad{"case generate --seed 1 --bmi-max abc --out x.xml", "--bmi-max = abc"},
             Bad{"case generate --seed 1 --difficulty 4-2 --out x.xml",
                 "--difficulty = 4-2 is not a range A-B"},
             Bad{"case generate --seed 1 --require \"tall\" --out x.xml", "expected a known term"},
             Bad{"case generate --out x.xml", "needs --seed N and --out FILE"},
             Bad{"case generate --seed 1 --colour red --out x.xml", "unknown option --colour"},
             Bad{"case stats --n 0", "--n = 0"},
             Bad{"case shuffle", "unknown action \"shuffle\""},
             Bad{"case validate", "needs at least one FILE"},
         }) {
        const auto result = runColonosim(bad.args);
        EXPECT_EQ(result.status, 2) << bad.args << "\n" << result.output;
        EXPECT_NE(result.output.find(bad.message), std::string::npos) << bad.args << "\n" << result.output;
    }
}

TEST_F(CaseCli, ImpossibleConstraintsExitTwo)
{
    const auto result =
        runColonosim("case generate --seed 1 --sex M --require hysterectomy --out " + path("x.xml"));
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.output.find("impossible constraints"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(path("x.xml")));
}

TEST_F(CaseCli, ValidateReportsFileAndLine)
{
    ASSERT_EQ(runColonosim("case generate --seed 8 --out " + path("good.xml")).status, 0);
    std::string text = read(path("good.xml"));
    text.replace(text.find("<height unit=\"cm\">"), 18, "<height unit=\"in\">");
    std::ofstream(path("bad.xml")) << text;
    const auto result = runColonosim("case validate " + path("good.xml") + " " + path("bad.xml"));
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.output.find(path("bad.xml") + ":16: patient.height: unit = \"in\", expected \"cm\""),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("good.xml: valid"), std::string::npos);
}

TEST_F(CaseCli, StatsJsonListsEveryRateWithItsSource)
{
    const auto result = runColonosim("case stats --n 3000 --seed 9 --json", true);
    ASSERT_EQ(result.status, 0) << result.output;
    const nlohmann::json list = nlohmann::json::parse(result.output);
    ASSERT_TRUE(list.is_array());
    EXPECT_GE(list.size(), 40u);
    bool adenoma = false;
    for (const nlohmann::json& entry : list) {
        for (const char* key : {"name", "source", "expected", "realised"}) {
            EXPECT_TRUE(entry.contains(key)) << entry.dump();
        }
        EXPECT_FALSE(entry["source"].get<std::string>().empty());
        adenoma = adenoma || entry["name"].get<std::string>().find("any_adenoma") != std::string::npos;
    }
    EXPECT_TRUE(adenoma);
}

TEST_F(CaseCli, StatsTableAndHelp)
{
    const auto table = runColonosim("case stats --n 500 --sex F");
    EXPECT_EQ(table.status, 0) << table.output;
    EXPECT_NE(table.output.find("any_adenoma_women"), std::string::npos);
    EXPECT_EQ(table.output.find("any_adenoma_men"), std::string::npos);
    const auto help = runColonosim("case --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.output.find("colonosim case generate --seed N"), std::string::npos);
    const auto top = runColonosim("--help");
    EXPECT_NE(top.output.find("case generate|validate|stats"), std::string::npos);
}

}  // namespace

namespace {

// `colonosim run --case FILE` runs a generated case (its anatomy, wall and
// environment); a broken case file is refused with its file:line errors.
TEST_F(CaseCli, RunDrivesTheProcedureWithAGeneratedCase)
{
    const std::string file = path("case.xml");
    ASSERT_EQ(runColonosim("case generate --seed 7 --out " + file).status, 0);
    const auto run = runColonosim(
        "run --case " + file + " --operator expert --max-time 1 --json --out " + path("run"), true);
    ASSERT_EQ(run.status, 0) << run.output;
    const nlohmann::json summary = nlohmann::json::parse(run.output);
    EXPECT_NEAR(summary["duration_s"].get<double>(), 1.0, 1e-9);
    EXPECT_TRUE(std::filesystem::exists(path("run") + "/session.trace"));

    std::ofstream(path("bad.xml")) << "<case><patient></case>";
    const auto bad =
        runColonosim("run --case " + path("bad.xml") + " --operator expert --out " + path("run2"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.output.find("bad.xml:"), std::string::npos) << bad.output;
    const auto both =
        runColonosim("run --default --case " + file + " --operator expert --out " + path("run3"));
    EXPECT_EQ(both.status, 2);
}

}  // namespace
