// `colonosim demo`: the whole headless pipeline on a fresh database. The
// database then holds the demo trainee's completed session with its metrics,
// and the report is a PDF; a second run adds a second session to the same
// trainee (the trainee's password is kept beside the database).
#include "db/Database.h"
#include "db/Records.h"
#include "tests/cli/RunColonosim.h"
#include "tests/db/TempDir.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace {

using namespace colonosim;

std::string firstBytes(const std::filesystem::path& file, size_t n)
{
    std::ifstream in(file, std::ios::binary);
    std::string bytes(n, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(n));
    bytes.resize(static_cast<size_t>(in.gcount()));
    return bytes;
}

TEST(Demo, NoSubcommandWithoutADisplayRunsItOnTheDefaultDatabaseCreatedOnFirstStart)
{
    // The README's run command on a machine with no display: a fresh home, so
    // the default database is created, seeded and used.
    test::TempDir home;
    const std::string command =
        "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM -u XDG_DATA_HOME HOME=" + home.path().string() +
        " COLONOSIM_ADMIN_PASSWORD= " + COLONOSIM_EXECUTABLE;
    const colonosim::testing::Result r = colonosim::testing::runCommand(command, "");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("administrator \"admin\" created with the password"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("4. report: "), std::string::npos) << r.output;
    const auto database = home.path() / ".local/share/colonosim/records.sqlite";
    ASSERT_TRUE(std::filesystem::exists(database)) << r.output;
    const auto report = home.path() / ".local/share/colonosim/demo/demo-student-report.pdf";
    EXPECT_EQ(firstBytes(report, 5), "%PDF-");
}

TEST(Demo, GeneratesRunsScoresAndReports)
{
    test::TempDir dir;
    const auto database = dir / "records.sqlite";
    const std::string arguments =
        "demo --db " + database.string() + " --out " + (dir / "out").string() + " --max-time 2 --json";
    const colonosim::testing::Result first = colonosim::testing::runColonosim(arguments, true);
    ASSERT_EQ(first.status, 0) << first.output;
    const nlohmann::json summary = nlohmann::json::parse(first.output);
    EXPECT_EQ(summary["database"].get<std::string>(), std::filesystem::absolute(database).string());
    const std::filesystem::path report = summary["report"].get<std::string>();
    EXPECT_EQ(report.parent_path(), dir / "out");
    EXPECT_EQ(firstBytes(report, 5), "%PDF-");
    EXPECT_TRUE(std::filesystem::exists(summary["case"].get<std::string>()));
    EXPECT_NEAR(summary["simulated_s"].get<double>(), 2.0, 0.01);

    const colonosim::testing::Result second = colonosim::testing::runColonosim(arguments, true);
    ASSERT_EQ(second.status, 0) << second.output;

    std::ifstream credentials(database.string() + ".demo-student");
    std::string password;
    ASSERT_TRUE(std::getline(credentials, password));
    db::Database records(database);
    db::Records access(records);
    const db::Actor student = access.authenticate("demo-student", password);
    const auto sessions = access.sessions(student, "demo-student");
    ASSERT_EQ(sessions.size(), 2u);
    EXPECT_EQ(sessions[0].id, summary["session"].get<qint64>());
    EXPECT_EQ(sessions[0].status, "completed");
    EXPECT_EQ(sessions[0].device, "scripted:expert");
    EXPECT_NEAR(sessions[0].duration, 2.0, 0.01);
    EXPECT_FALSE(sessions[0].metrics.empty()) << "the session was scored: its metrics are stored";
}

TEST(Demo, RefusesOutOfRangeTime)
{
    const colonosim::testing::Result r = colonosim::testing::runColonosim("demo --max-time 0.1");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.output.find("--max-time"), std::string::npos) << r.output;
}

}  // namespace
