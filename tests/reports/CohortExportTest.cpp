// A cohort's export is written whole or not at all: stopped before it starts
// or between two trainees, or refused because the target exists, it leaves
// nothing at the target (and no partial file); completed, it holds every
// trainee's sessions. A student may not export another's records.
#include "trainer_ui/reports/CohortExport.h"
#include "db/Database.h"
#include "db/Records.h"
#include "tests/db/TempDir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace {

using namespace colonosim;

struct Export : ::testing::Test {
    test::TempDir dir;
    db::Database database{dir / "records.sqlite"};
    db::Records records{database};
    db::Actor admin;
    std::vector<std::string> trainees{"ada", "bob", "cy"};

    void SetUp() override
    {
        admin = records.bootstrapAdministrator("admin", "admin-password");
        for (const std::string& t : trainees) {
            records.addUser(admin, t, db::Role::Student, t + "-password");
            const db::Actor student = records.authenticate(t, t + "-password");
            for (int k = 0; k < 2; ++k) {
                db::SessionResult result;
                result.duration = 1.0 + k;
                records.completeSession(student, records.beginSession(student, std::nullopt, "t", "keyboard"),
                                        result);
            }
        }
    }
    [[nodiscard]] bool leftovers(const std::filesystem::path& out) const
    {
        return std::filesystem::exists(out) || std::filesystem::exists(out.string() + ".partial");
    }
};

TEST_F(Export, CsvHoldsEveryTraineesSessionsAndReportsProgress)
{
    const auto out = dir / "cohort.csv";
    std::vector<std::pair<int, int>> seen;
    const auto outcome =
        reports::exportCohort(reports::ReportFormat::Csv, database, records, admin, trainees, out, {},
                              [&](int done, int total) { seen.emplace_back(done, total); });
    ASSERT_EQ(outcome, reports::ExportOutcome::Written);
    EXPECT_EQ(seen, (std::vector<std::pair<int, int>>{{1, 3}, {2, 3}, {3, 3}}));
    std::ifstream in(out);
    std::string line;
    int rows = -1;
    while (std::getline(in, line)) {
        ++rows;
    }
    EXPECT_EQ(rows, 6);
    EXPECT_FALSE(std::filesystem::exists(out.string() + ".partial"));
}

TEST_F(Export, StoppedBeforeOrBetweenTraineesLeavesNothing)
{
    for (const auto format : {reports::ReportFormat::Csv, reports::ReportFormat::Xapi}) {
        const auto before = dir / ("before." + reports::formatName(format));
        std::stop_source stopped;
        stopped.request_stop();
        EXPECT_EQ(
            reports::exportCohort(format, database, records, admin, trainees, before, stopped.get_token()),
            reports::ExportOutcome::Cancelled);
        EXPECT_FALSE(leftovers(before));

        const auto between = dir / ("between." + reports::formatName(format));
        std::stop_source source;
        const auto outcome = reports::exportCohort(format, database, records, admin, trainees, between,
                                                   source.get_token(), [&](int done, int) {
                                                       if (done == 1) {
                                                           source.request_stop();
                                                       }
                                                   });
        EXPECT_EQ(outcome, reports::ExportOutcome::Cancelled);
        EXPECT_FALSE(leftovers(between));
    }
}

TEST_F(Export, RefusesAnExistingTargetAndLeavesItAlone)
{
    const auto out = dir / "taken.csv";
    std::ofstream(out) << "keep me\n";
    EXPECT_THROW(
        reports::exportCohort(reports::ReportFormat::Csv, database, records, admin, trainees, out, {}),
        std::runtime_error);
    std::ifstream in(out);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "keep me");
}

TEST_F(Export, AStudentMayNotExportAnothersRecords)
{
    const db::Actor ada = records.authenticate("ada", "ada-password");
    const auto out = dir / "stolen.csv";
    EXPECT_THROW(reports::exportCohort(reports::ReportFormat::Csv, database, records, ada, trainees, out, {}),
                 db::AccessDenied);
    EXPECT_FALSE(leftovers(out));
}

}  // namespace
