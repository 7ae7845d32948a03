// The core curriculum reads cleanly and its constraints drive the case
// generator; bad files are refused with file:line naming field and value;
// progression unlocks after two consecutive met benchmarks; certification
// rules evaluate per trainee.
#include "curricula/Curriculum.h"
#include "case_generator/CaseGenerator.h"
#include "curricula/Certification.h"
#include "curricula/Progression.h"
#include "simcore/scope/ScopeParameters.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace {

using namespace colonosim;
using curricula::TaskState;

const curricula::Curriculum& core()
{
    static const curricula::Curriculum c = [] {
        const auto read = curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
        for (const auto& e : read.errors) {
            ADD_FAILURE() << e;
        }
        return read.value.value_or(curricula::Curriculum{});
    }();
    return c;
}

TEST(Curriculum, TheCoreFileReadsAndIsOrderedEasyToHard)
{
    const auto& c = core();
    EXPECT_EQ(c.name, "colonoscopy-core");
    ASSERT_EQ(c.modules.size(), 6u);
    EXPECT_EQ(c.modules.front().id, "orientation");
    EXPECT_EQ(c.modules.back().id, "complex");
    for (const auto& task : c.tasks) {
        EXPECT_FALSE(task.objectives.empty()) << task.id;
        EXPECT_FALSE(task.benchmark.empty()) << task.id;
        if (task.module == "therapy") {
            EXPECT_FALSE(task.available) << task.id;
            EXPECT_NE(task.unavailableReason.find("instruments"), std::string::npos);
        } else {
            EXPECT_TRUE(task.available) << task.id;
        }
        // The imager is a learning aid: shown everywhere except the complex-anatomy assessment.
        EXPECT_EQ(task.shapeView, task.id != "complex-anatomy") << task.id;
    }
}

TEST(Curriculum, EveryTaskConstraintGivesACase)
{
    const cases::CaseGenerator generator;
    for (const auto& task : core().tasks) {
        const cases::Case c = generator.generate(7, task.constraints);
        if (task.constraints.difficultyMax) {
            EXPECT_LE(c.difficulty.level, *task.constraints.difficultyMax) << task.id;
        }
    }
}

// Every task reaches the cecum, and the simulated colon pleats onto the shaft
// by a few centimetres only (docs/known-limits.md, "Out of scope, not
// stalled"): a colon longer than the scope is out of reach, and 16% of the
// population's are. Each task's cases keep within the scope's working length.
TEST(Curriculum, EveryTaskDrawsColonsNoLongerThanTheScope)
{
    const cases::CaseGenerator generator;
    const double scopeLength = scope::ScopeParameters::workingLengthSpec.defaultValue;
    int longest = 0;
    for (const auto& task : core().tasks) {
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            const cases::Case c = generator.generate(seed, task.constraints);
            const double length = c.anatomy.colonLength();
            ASSERT_LE(length, scopeLength) << task.id << ", seed " << seed;
            longest = std::max(longest, static_cast<int>(length * 100.0));
        }
    }
    // The bound is not so tight that it leaves only short colons.
    EXPECT_GE(longest, 160);
}

struct BadFile {
    const char* xml;
    const char* expected;
};

class CurriculumErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(CurriculumErrors, AreRefusedWithLineAndField)
{
    const auto read = curricula::parseCurriculum(GetParam().xml, "bad.xml");
    ASSERT_FALSE(read.ok());
    bool found = false;
    for (const auto& e : read.errors) {
        found = found || e.find(GetParam().expected) != std::string::npos;
    }
    EXPECT_TRUE(found) << read.errors.front();
}

constexpr const char* kTask = R"(<task id="a" title="A" benchmark="b"><instructions>i</instructions>)"
                              R"(<objective>o</objective>)";

const std::string kDifficulty =
    std::string("<curriculum name=\"c\" version=\"1\"><module id=\"m\" title=\"M\">\n") + kTask +
    "<constraints difficulty_max=\"9\"/></task></module></curriculum>";
const std::string kRequire =
    std::string("<curriculum name=\"c\" version=\"1\"><module id=\"m\" title=\"M\">") + kTask +
    "<constraints require=\"wibble(3mm\"/></task></module></curriculum>";
const std::string kPrerequisite =
    std::string("<curriculum name=\"c\" version=\"1\"><module id=\"m\" title=\"M\">") + kTask +
    "<constraints/><prerequisite task=\"later\"/></task></module></curriculum>";
const std::string kUnavailable =
    "<curriculum name=\"c\" version=\"1\"><module id=\"m\" title=\"M\"><task id=\"a\" title=\"A\" "
    "benchmark=\"b\" "
    "available=\"false\"><instructions>i</instructions><objective>o</objective><constraints/></task></module>"
    "</curriculum>";

const std::string kShapeView =
    "<curriculum name=\"c\" version=\"1\"><module id=\"m\" title=\"M\"><task id=\"a\" title=\"A\" "
    "benchmark=\"b\" "
    "shape_view=\"sometimes\"><instructions>i</instructions><objective>o</objective><constraints/></task>"
    "</module></curriculum>";

INSTANTIATE_TEST_SUITE_P(
    Table, CurriculumErrors,
    ::testing::Values(BadFile{"<curriculum", "bad.xml:1:"},
                      BadFile{kDifficulty.c_str(), "bad.xml:2: difficulty_max = \"9\" is out of range 1-5"},
                      BadFile{kRequire.c_str(), "require = \"wibble(3mm\""},
                      BadFile{kPrerequisite.c_str(), "prerequisite \"later\" is not a task defined earlier"},
                      BadFile{kUnavailable.c_str(), "must say why"},
                      BadFile{kShapeView.c_str(), "shape_view = \"sometimes\" is not one of true, false"},
                      BadFile{"<course/>", "root element must be <curriculum>"}));

TEST(Progression, TwoConsecutiveMetBenchmarksUnlockWhatFollows)
{
    using curricula::Attempt;
    const auto& c = core();
    auto states = curricula::progression(c, {});
    EXPECT_EQ(states.at("navigation-straight"), TaskState::Unlocked);
    EXPECT_EQ(states.at("navigation-flexures"), TaskState::Locked);
    EXPECT_EQ(states.at("polypectomy"), TaskState::Unavailable);
    // met, missed, met: not two in a row.
    states = curricula::progression(
        c, {{"navigation-straight", true}, {"navigation-straight", false}, {"navigation-straight", true}});
    EXPECT_EQ(states.at("navigation-straight"), TaskState::Unlocked);
    EXPECT_EQ(states.at("navigation-flexures"), TaskState::Locked);
    // ... then met again: two in a row.
    states = curricula::progression(c, {{"navigation-straight", true},
                                        {"navigation-straight", false},
                                        {"navigation-straight", true},
                                        {"navigation-straight", true}});
    EXPECT_EQ(states.at("navigation-straight"), TaskState::Proficient);
    EXPECT_EQ(states.at("navigation-flexures"), TaskState::Unlocked);
    // Attempts on a locked task do not count.
    states = curricula::progression(c, {{"loop-sigmoid", true}, {"loop-sigmoid", true}});
    EXPECT_EQ(states.at("loop-sigmoid"), TaskState::Locked);
    // Two prerequisites: complex-anatomy needs loop-transverse and detect-polyps.
    std::vector<Attempt> all;
    for (const char* t : {"navigation-straight", "navigation-flexures", "loop-sigmoid", "loop-transverse"}) {
        all.push_back({t, true});
        all.push_back({t, true});
    }
    states = curricula::progression(c, all);
    EXPECT_EQ(states.at("complex-anatomy"), TaskState::Locked);
    for (const char* t : {"withdrawal", "detect-polyps"}) {
        all.push_back({t, true});
        all.push_back({t, true});
    }
    states = curricula::progression(c, all);
    EXPECT_EQ(states.at("complex-anatomy"), TaskState::Unlocked);
    EXPECT_EQ(states.at("polypectomy"), TaskState::Unavailable);
}

TEST(Certification, RulesPerTrainee)
{
    const auto read = curricula::parseRuleSet(curricula::coreRuleSetXml(), "certification-rules.xml");
    ASSERT_TRUE(read.ok()) << read.errors.front();
    const auto& rules = *read.value;
    for (const auto& r : rules.rules) {
        EXPECT_FALSE(r.source.empty()) << r.id;
    }
    // 200 sessions: cecum reached in all but 1 of the last 20, 8 min withdrawal,
    // lesions in every 2nd session and one detected in every 4th (50% of those),
    // discomfort peak 7 in 5% of sessions, a perforation at session 185.
    std::vector<scoring::MetricValues> sessions;
    for (int n = 0; n < 200; ++n) {
        scoring::MetricValues m;
        m["cecal_intubation"] = n == 195 ? 0.0 : 1.0;
        m["withdrawal_time"] = n == 195 ? 0.0 : 480.0;
        m["lesions_present"] = n % 2 == 0 ? 1.0 : 0.0;
        m["lesions_detected"] = n % 4 == 0 ? 1.0 : 0.0;
        m["discomfort_peak"] = n % 20 == 0 ? 7.0 : 2.0;
        m["perforation"] = n == 185 ? 1.0 : 0.0;
        sessions.push_back(m);
    }
    auto status = [&](const std::vector<scoring::MetricValues>& s) {
        std::map<std::string, std::pair<bool, double>> out;
        for (const auto& r : curricula::evaluate(rules, s)) {
            out[r.rule->id] = {r.met, r.observed};
        }
        return out;
    };
    auto st = status(sessions);
    EXPECT_TRUE(st.at("procedures").first);
    EXPECT_TRUE(st.at("cecal-intubation").first);
    EXPECT_DOUBLE_EQ(st.at("cecal-intubation").second, 0.95);
    EXPECT_TRUE(st.at("lesion-detection").first);
    EXPECT_DOUBLE_EQ(st.at("lesion-detection").second, 0.5);
    EXPECT_TRUE(st.at("withdrawal-time").first);
    EXPECT_DOUBLE_EQ(st.at("withdrawal-time").second, 480.0);
    EXPECT_TRUE(st.at("no-perforation").first);  // the perforation at 185 is before the last 10
    EXPECT_TRUE(st.at("comfort").first);
    EXPECT_DOUBLE_EQ(st.at("comfort").second, 0.05);
    sessions[185]["perforation"] = 0.0;
    sessions[199]["perforation"] = 1.0;
    EXPECT_FALSE(status(sessions).at("no-perforation").first);
    sessions[199]["perforation"] = 0.0;
    EXPECT_TRUE(status(sessions).at("no-perforation").first);
    sessions.resize(199);
    EXPECT_FALSE(status(sessions).at("procedures").first);
}

TEST(Certification, BadRuleFilesAreRefused)
{
    const auto read = curricula::parseRuleSet("<certification name=\"x\" version=\"1\">\n<rule id=\"a\" "
                                              "kind=\"share_at_least\" metric=\"nonsense\" "
                                              "value=\"2\" description=\"d\" source=\"s\"/></certification>",
                                              "rules.xml");
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.errors.at(0), "rules.xml:2: metric \"nonsense\" is not a declared scoring metric");
    EXPECT_EQ(read.errors.at(1), "rules.xml:2: value = 2.000000 is out of range 0-1 for a share");
}

TEST(Curriculum, TheShippedFilesValidateAgainstTheirSchemas)
{
    // xmllint (libxml2-utils, from the setup script) validates; the readers
    // check the same constraints themselves, so the XSDs must not drift.
    const std::string root = COLONOSIM_SOURCE_DIR;
    for (const auto& [file, schema] : {std::pair{"colonoscopy-core.xml", "curriculum.xsd"},
                                       std::pair{"certification-rules.xml", "certification.xsd"}}) {
        const std::string command = "xmllint --noout --schema " + root + "/curricula/schema/" + schema + " " +
                                    root + "/curricula/" + file + " >/dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
    }
    // A schema does refuse a broken file: a task without its title.
    std::string text = curricula::coreCurriculumXml();
    const size_t title = text.find(" title=\"Navigate an easy colon\"");
    ASSERT_NE(title, std::string::npos);
    text.erase(title, std::string(" title=\"Navigate an easy colon\"").size());
    const std::filesystem::path broken =
        std::filesystem::temp_directory_path() /
        ("colonosim-broken-curriculum-" + std::to_string(::getpid()) + ".xml");
    std::ofstream(broken) << text;
    EXPECT_NE(std::system(("xmllint --noout --schema " + root + "/curricula/schema/curriculum.xsd " +
                           broken.string() + " >/dev/null 2>&1")
                              .c_str()),
              0);
    std::filesystem::remove(broken);
}

}  // namespace
