// `colonosim rules` as an administrator uses it: the shipped set listed as
// version 1 and active, an invalid file refused with file:line, a new version
// imported and activated, progress judged by it and naming it, and a student
// refused. Passwords travel in environment variables only.
#include "RunColonosim.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace {

using colonosim::testing::Result;
using colonosim::testing::runColonosim;

std::string read(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class RulesCli : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir =
            std::filesystem::temp_directory_path() / ("colonosim-rules-cli-" + std::to_string(::getpid()));
        std::filesystem::create_directories(m_dir);
        m_db = " --db " + (m_dir / "records.sqlite").string();
        ASSERT_EQ(as("COLONOSIM_ADMIN_PASSWORD=admin-secret-1 COLONOSIM_PASSWORD=admin-secret-1 "
                     "COLONOSIM_NEW_PASSWORD=ada-secret-1",
                     "user add ada --role student --as admin")
                      .status,
                  0);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }

    Result as(const std::string& env, const std::string& arguments)
    {
        return colonosim::testing::runCommand("env " + env + " " + COLONOSIM_EXECUTABLE, arguments + m_db);
    }
    Result admin(const std::string& arguments) { return as("COLONOSIM_PASSWORD=admin-secret-1", arguments); }

    /// The source tree's core rule set with `from` replaced by `to`, written to `name`.
    std::string variant(const std::string& name, const std::string& from, const std::string& to)
    {
        std::string xml =
            read(std::filesystem::path(COLONOSIM_SOURCE_DIR) / "curricula/certification-rules.xml");
        xml.replace(xml.find(from), from.size(), to);
        const std::filesystem::path file = m_dir / name;
        std::ofstream(file, std::ios::binary) << xml;
        return file.string();
    }

    std::filesystem::path m_dir;
    std::string m_db;
};

TEST_F(RulesCli, ImportActivateAndProgressNamesTheActiveSet)
{
    const Result first = admin("rules list --json --as admin");
    ASSERT_EQ(first.status, 0) << first.output;
    const auto listed = nlohmann::json::parse(first.output.substr(first.output.find('[')));
    ASSERT_EQ(listed.size(), 1U);
    EXPECT_EQ(listed[0]["name"], "colonoscopy-simulated");
    EXPECT_EQ(listed[0]["version"], 1);
    EXPECT_TRUE(listed[0]["imported_by"].is_null());
    EXPECT_TRUE(listed[0]["active"].get<bool>());

    const std::string bad = variant("bad.xml", "kind=\"none_in_last\"", "kind=\"never\"");
    const Result refused = admin("rules import " + bad + " --as admin");
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.output.find(bad + ":25: kind = \"never\" is not one of"), std::string::npos)
        << refused.output;

    const std::string good = variant("revised.xml", "version=\"1\">", "version=\"2\">");
    const Result imported = admin("rules import " + good + " --as admin");
    ASSERT_EQ(imported.status, 0) << imported.output;
    EXPECT_NE(imported.output.find("imported colonoscopy-simulated version 2 (not active"), std::string::npos)
        << imported.output;
    const Result again = admin("rules import " + good + " --as admin");
    EXPECT_EQ(again.status, 2);
    EXPECT_NE(again.output.find(good +
                                ":11: <certification> version = 2 is already taken or older: a new rule "
                                "set needs a version of at least 3"),
              std::string::npos)
        << again.output;
    const Result activated = admin("rules activate 2 --as admin");
    ASSERT_EQ(activated.status, 0) << activated.output;
    EXPECT_NE(activated.output.find("active: colonoscopy-simulated version 2"), std::string::npos);
    const Result missing = admin("rules activate 7 --as admin");
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.output.find("version 7 is not stored: the stored versions are 1, 2"), std::string::npos)
        << missing.output;

    const Result progress = as("COLONOSIM_PASSWORD=ada-secret-1", "progress --user ada --json");
    ASSERT_EQ(progress.status, 0) << progress.output;
    const auto p = nlohmann::json::parse(progress.output.substr(progress.output.find('{')));
    EXPECT_EQ(p["certification_rule_set"]["version"], 2);
    EXPECT_EQ(p["certification_rule_set"]["name"], "colonoscopy-simulated");
}

TEST_F(RulesCli, AStudentMayListButNotImportOrActivate)
{
    const std::string good = variant("revised.xml", "version=\"1\">", "version=\"2\">");
    const std::string ada = "COLONOSIM_PASSWORD=ada-secret-1";
    EXPECT_EQ(as(ada, "rules list --as ada").status, 0);
    const Result import = as(ada, "rules import " + good + " --as ada");
    EXPECT_EQ(import.status, 2);
    EXPECT_NE(import.output.find("refused: ada (student) may not import certification rule sets"),
              std::string::npos)
        << import.output;
    const Result activate = as(ada, "rules activate 1 --as ada");
    EXPECT_EQ(activate.status, 2);
    EXPECT_NE(activate.output.find("may not activate certification rule sets"), std::string::npos);
    const Result noPassword = runColonosim("rules list --as admin" + m_db);
    EXPECT_EQ(noPassword.status, 2);
}

}  // namespace
