// The case library and its assignments: who may list, read and assign cases,
// an assignment to a cohort reaching its members, and the audit trail.
#include "db/CaseLibrary.h"
#include "db/Cohorts.h"
#include "db/Database.h"
#include "db/Records.h"
#include "tests/db/TempDir.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;
using db::Actor;

struct Library : ::testing::Test {
    test::TempDir dir;
    db::Database database{dir / "records.sqlite"};
    db::Records records{database};
    db::CaseLibrary library{database};
    Actor admin, teacher, ada, bob;
    qint64 caseId = 0;

    void SetUp() override
    {
        admin = records.bootstrapAdministrator("root", "root-password");
        records.addUser(admin, "teacher", db::Role::Instructor, "teacher-password");
        records.addUser(admin, "ada", db::Role::Student, "ada-password");
        records.addUser(admin, "bob", db::Role::Student, "bob-password");
        records.addCohort(admin, "A");
        records.addCohort(admin, "B");
        records.addMember(admin, "A", "ada");
        records.addMember(admin, "B", "bob");
        records.assignInstructor(admin, "A", "teacher");
        teacher = records.authenticate("teacher", "teacher-password");
        ada = records.authenticate("ada", "ada-password");
        bob = records.authenticate("bob", "bob-password");
        caseId = records.storeCase(teacher, "case-1.xml", "<case seed=\"1\"/>");
    }
};

TEST_F(Library, InstructorAssignsToTheirCohortAndItsMembersSeeTheCase)
{
    EXPECT_EQ(library.cases(teacher).size(), 1u);
    EXPECT_TRUE(library.cases(ada).empty()) << "nothing is assigned to ada yet";
    EXPECT_THROW((void)library.caseXml(ada, caseId), db::AccessDenied);

    library.assignToCohort(teacher, caseId, "A");
    ASSERT_EQ(library.cases(ada).size(), 1u);
    EXPECT_EQ(library.caseXml(ada, caseId), "<case seed=\"1\"/>");
    const auto assigned = library.assignments(teacher, "ada");
    ASSERT_EQ(assigned.size(), 1u);
    EXPECT_EQ(assigned[0].cohort, "A");
    EXPECT_EQ(assigned[0].assignedBy, "teacher");
    EXPECT_EQ(assigned[0].caseName, "case-1.xml");
    EXPECT_TRUE(library.cases(bob).empty()) << "bob is in cohort B, not A";

    // Assigning twice keeps one assignment.
    EXPECT_EQ(library.assignToCohort(teacher, caseId, "A"), assigned[0].id);
}

TEST_F(Library, RefusedAssignmentsNameTheRule)
{
    try {
        library.assignToCohort(ada, caseId, "A");
        FAIL() << "a student assigned a case";
    } catch (const db::AccessDenied& e) {
        EXPECT_NE(std::string(e.what()).find("only instructors and administrators"), std::string::npos);
    }
    EXPECT_THROW(library.assignToTrainee(ada, caseId, "ada"), db::AccessDenied);
    EXPECT_THROW(library.assignToCohort(teacher, caseId, "B"), db::AccessDenied)
        << "the teacher is not assigned to cohort B";
    EXPECT_THROW(library.assignToTrainee(teacher, caseId, "bob"), db::AccessDenied)
        << "bob is not a student of the teacher's cohorts";
    EXPECT_THROW((void)library.assignments(teacher, "bob"), db::AccessDenied);
    EXPECT_THROW(library.assignToTrainee(admin, caseId, "teacher"), db::DatabaseError)
        << "cases go to students";
    EXPECT_THROW(library.assignToTrainee(admin, caseId + 100, "ada"), db::DatabaseError);
    EXPECT_THROW(library.assignToCohort(admin, caseId, "no-such-cohort"), db::DatabaseError);
}

TEST_F(Library, AdministratorAssignsToAnyoneAndTheAuditNamesWho)
{
    library.assignToTrainee(admin, caseId, "bob");
    ASSERT_EQ(library.assignments(bob, "bob").size(), 1u);
    EXPECT_TRUE(library.assignments(bob, "bob")[0].cohort.empty());
    bool audited = false;
    for (const auto& row : records.audit(admin)) {
        audited = audited || (row.table == "case_assignments" && row.actor == "root");
    }
    EXPECT_TRUE(audited);
}

TEST_F(Library, CohortsAreReadAsEachRoleMay)
{
    ASSERT_EQ(db::readableCohorts(database, admin).size(), 2u);
    const auto mine = db::readableCohorts(database, teacher);
    ASSERT_EQ(mine.size(), 1u);
    EXPECT_EQ(mine[0].name, "A");
    EXPECT_EQ(mine[0].members, std::vector<std::string>{"ada"});
    EXPECT_EQ(mine[0].instructors, std::vector<std::string>{"teacher"});
    const auto bobs = db::readableCohorts(database, bob);
    ASSERT_EQ(bobs.size(), 1u);
    EXPECT_EQ(bobs[0].name, "B");
}

}  // namespace
