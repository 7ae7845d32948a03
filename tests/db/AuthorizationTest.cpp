// The authorization matrix: every role against every operation of the data-
// access layer, both the allowed and the refused cells. The fixture: an
// administrator, an instructor assigned to cohort "A", student ada in "A" and
// student bob in no cohort of the instructor's (the matrix adds bob to cohort
// "B" and the instructor to cohort "C", so the instructor never gains bob).
#include "curricula/Certification.h"
#include "db/CertificationRules.h"
#include "db/Database.h"
#include "db/Records.h"
#include "tests/db/TempDir.h"

#include <gtest/gtest.h>

#include <functional>

namespace {

using namespace colonosim;
using db::Actor;
using db::Records;

struct Cell {
    const char* operation;
    std::function<void(Records&, const Actor&, qint64 bobSession)> run;
    bool administrator, instructor, student;
};

TEST(Authorization, EveryRoleAgainstEveryOperation)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    Records records(database);
    const Actor admin = records.bootstrapAdministrator("root", "root-password");
    records.addUser(admin, "teacher", db::Role::Instructor, "teacher-password");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
    records.addUser(admin, "bob", db::Role::Student, "bob-password");
    records.addCohort(admin, "A");
    records.addCohort(admin, "B");
    records.addCohort(admin, "C");
    records.addMember(admin, "A", "ada");
    records.assignInstructor(admin, "A", "teacher");
    const Actor teacher = records.authenticate("teacher", "teacher-password");
    const Actor ada = records.authenticate("ada", "ada-password");
    const Actor bob = records.authenticate("bob", "bob-password");
    const qint64 bobSession = records.beginSession(bob, std::nullopt, "t", "keyboard");
    records.completeSession(bob, bobSession, db::SessionResult{});
    const qint64 adaSession = records.beginSession(ada, std::nullopt, "t", "keyboard");
    records.completeSession(ada, adaSession, db::SessionResult{});

    const std::vector<Cell> matrix = {
        {"add a user",
         [](Records& r, const Actor& a, qint64) {
             r.addUser(a, "new-" + a.name, db::Role::Student, "pass-word-1");
         },
         true, false, false},
        {"change another's password",
         [](Records& r, const Actor& a, qint64) { r.setPassword(a, "bob", "bob-password"); }, true, false,
         false},
        {"change one's own password",
         [](Records& r, const Actor& a, qint64) { r.setPassword(a, a.name, a.name + "-password"); }, true,
         true, true},
        {"add a cohort", [](Records& r, const Actor& a, qint64) { r.addCohort(a, "cohort-" + a.name); }, true,
         false, false},
        {"add a cohort member", [](Records& r, const Actor& a, qint64) { r.addMember(a, "B", "bob"); }, true,
         false, false},
        {"assign an instructor",
         [](Records& r, const Actor& a, qint64) { r.assignInstructor(a, "C", "teacher"); }, true, false,
         false},
        {"store a curriculum",
         [](Records& r, const Actor& a, qint64) { r.storeCurriculum(a, "c-" + a.name, "<curriculum/>"); },
         true, false, false},
        {"store a benchmark set",
         [](Records& r, const Actor& a, qint64) { r.storeBenchmarkSet(a, "b-" + a.name, 1, "{}"); }, true,
         false, false},
        {"re-score a session",
         [](Records& r, const Actor& a, qint64 s) {
             r.rescore(a, s, {{"composite", 1.0}}, 1);
         },
         true, false, false},
        {"issue a certificate",
         [](Records& r, const Actor& a, qint64) {
             r.issueCertificate(a, "bob", "sha-" + a.name, "sig", "key");
         },
         true, false, false},
        {"import a certification rule set",
         [&database](Records&, const Actor& a, qint64) {
             // A new version each time it is allowed, so each import is a real one.
             db::CertificationRules rules(database);
             const int next = rules.versions(a).back().version + 1;
             std::string xml = curricula::coreRuleSetXml();
             xml.replace(xml.find("version=\"1\""), 11, "version=\"" + std::to_string(next) + "\"");
             (void)rules.import(a, xml, "rules.xml");
         },
         true, false, false},
        {"activate a certification rule set",
         [&database](Records&, const Actor& a, qint64) { db::CertificationRules(database).activate(a, 1); },
         true, false, false},
        {"read the active certification rule set",
         [&database](Records&, const Actor& a, qint64) {
             (void)db::CertificationRules(database).active(a);
             (void)db::CertificationRules(database).versions(a);
         },
         true, true, true},
        {"store a case (the case a session runs on)",
         [](Records& r, const Actor& a, qint64) {
             (void)r.storeCase(a, "case-" + a.name + ".xml", "<case/>");
         },
         true, true, true},
        {"read a curriculum", [](Records& r, const Actor& a, qint64) { (void)r.curriculum(a, "core"); }, true,
         true, true},
        {"read the audit log", [](Records& r, const Actor& a, qint64) { (void)r.audit(a); }, true, false,
         false},
        {"take a backup",
         [&dir](Records& r, const Actor& a, qint64) { r.backup(a, dir / ("backup-" + a.name + ".sqlite")); },
         true, false, false},
        {"run a session",
         [](Records& r, const Actor& a, qint64) { (void)r.beginSession(a, std::nullopt, "t", "keyboard"); },
         true, true, true},
        {"read ada's sessions (in cohort A)",
         [](Records& r, const Actor& a, qint64) { (void)r.sessions(a, "ada"); }, true, true, true},
        {"read bob's sessions (no cohort)",
         [](Records& r, const Actor& a, qint64) { (void)r.sessions(a, "bob"); }, true, false, false},
        {"read bob's learning curve",
         [](Records& r, const Actor& a, qint64) { (void)r.learningCurve(a, "bob", "total_time"); }, true,
         false, false},
        {"read bob's progress",
         [](Records& r, const Actor& a, qint64) { (void)r.progress(a, "bob", "core"); }, true, false, false},
        {"read bob's recording", [](Records& r, const Actor& a, qint64 s) { (void)r.sessionRecording(a, s); },
         true, false, false},
        {"read bob's trace", [](Records& r, const Actor& a, qint64 s) { (void)r.sessionTrace(a, s); }, true,
         false, false},
        {"read bob's case", [](Records& r, const Actor& a, qint64 s) { (void)r.sessionCase(a, s); }, true,
         false, false},
        {"complete bob's session",
         [](Records& r, const Actor& a, qint64 s) { r.completeSession(a, s, db::SessionResult{}); }, false,
         false, false},
    };
    for (const Cell& cell : matrix) {
        for (const auto& [actor, allowed] :
             {std::pair{admin, cell.administrator}, std::pair{teacher, cell.instructor},
              std::pair{ada, cell.student}}) {
            SCOPED_TRACE(std::string(cell.operation) + " as " + actor.name);
            if (allowed) {
                EXPECT_NO_THROW(cell.run(records, actor, bobSession));
            } else {
                try {
                    cell.run(records, actor, bobSession);
                    ADD_FAILURE() << "allowed, expected refused";
                } catch (const db::AccessDenied& error) {
                    EXPECT_NE(std::string(error.what()).find(actor.name), std::string::npos) << error.what();
                }
            }
        }
    }
}

TEST(Authorization, UserListsAreScopedByRole)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    Records records(database);
    const Actor admin = records.bootstrapAdministrator("root", "root-password");
    records.addUser(admin, "teacher", db::Role::Instructor, "teacher-password");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
    records.addUser(admin, "bob", db::Role::Student, "bob-password");
    records.addCohort(admin, "A");
    records.addMember(admin, "A", "ada");
    records.assignInstructor(admin, "A", "teacher");
    auto names = [&](const Actor& actor) {
        std::vector<std::string> out;
        for (const auto& u : records.listUsers(actor)) {
            out.push_back(u.name);
        }
        return out;
    };
    EXPECT_EQ(names(admin), (std::vector<std::string>{"ada", "bob", "root", "teacher"}));
    EXPECT_EQ(names(records.authenticate("teacher", "teacher-password")),
              (std::vector<std::string>{"ada", "teacher"}));
    EXPECT_EQ(names(records.authenticate("bob", "bob-password")), (std::vector<std::string>{"bob"}));
}

}  // namespace
