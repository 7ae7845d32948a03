// Schema migrations: from an empty file and from every earlier version to the
// latest, keeping the data; a newer file is refused; the audit log is append-only.
#include "db/Database.h"
#include "db/Records.h"
#include "db/Schema.h"
#include "tests/db/TempDir.h"

#include <QSqlError>
#include <QSqlQuery>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace colonosim;

/// A connection to `path` outside the Database class, for setting up old versions.
class RawConnection {
public:
    explicit RawConnection(const std::filesystem::path& path)
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("raw"));
        db.setDatabaseName(QString::fromStdString(path.string()));
        EXPECT_TRUE(db.open());
    }
    ~RawConnection()
    {
        QSqlDatabase::database(QStringLiteral("raw")).close();
        QSqlDatabase::removeDatabase(QStringLiteral("raw"));
    }
    [[nodiscard]] QSqlDatabase db() const { return QSqlDatabase::database(QStringLiteral("raw")); }
    bool exec(const QString& sql) const
    {
        QSqlQuery query(db());
        return query.exec(sql);
    }
    [[nodiscard]] long long scalar(const QString& sql) const
    {
        QSqlQuery query(db());
        EXPECT_TRUE(query.exec(sql)) << query.lastError().text().toStdString();
        EXPECT_TRUE(query.next());
        return query.value(0).toLongLong();
    }
};

TEST(Migrations, FromEmptyReachTheLatestVersion)
{
    test::TempDir dir;
    {
        db::Database database(dir / "records.sqlite");
        QSqlDatabase c = database.connection();
        EXPECT_EQ(db::schemaVersion(c), db::latestSchemaVersion());
        QSqlQuery query(c);
        ASSERT_TRUE(query.exec(QStringLiteral("PRAGMA journal_mode")) && query.next());
        EXPECT_EQ(query.value(0).toString(), QStringLiteral("wal"));
        ASSERT_TRUE(query.exec(QStringLiteral("PRAGMA foreign_keys")) && query.next());
        EXPECT_EQ(query.value(0).toInt(), 1);
    }
    RawConnection raw(dir / "records.sqlite");
    for (const char* table :
         {"users", "cohorts", "cohort_members", "cohort_instructors", "cases", "curricula", "sessions",
          "events", "metrics", "scores", "progress", "certificates", "audit", "benchmark_sets",
          "case_assignments", "certification_rule_sets"}) {
        EXPECT_EQ(raw.scalar(QStringLiteral(
                                 "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = '%1'")
                                 .arg(QString::fromLatin1(table))),
                  1)
            << table;
    }
}

class FromEarlierVersion : public ::testing::TestWithParam<int> {};

TEST_P(FromEarlierVersion, KeepsTheDataAndReachesTheLatest)
{
    const int start = GetParam();
    test::TempDir dir;
    {
        RawConnection raw(dir / "records.sqlite");
        QSqlDatabase c = raw.db();
        db::migrate(c, start);
        EXPECT_EQ(db::schemaVersion(c), start);
        if (start >= 1) {
            ASSERT_TRUE(raw.exec(QStringLiteral(
                "INSERT INTO users (name, role, password_hash) VALUES ('ada', 'student', 'x')")));
            ASSERT_TRUE(raw.exec(QStringLiteral("INSERT INTO sessions (user_id, device, owner, status) "
                                                "VALUES (1, 'keyboard', 'h:1', 'completed')")));
            ASSERT_TRUE(
                raw.exec(QStringLiteral("INSERT INTO scores (session_id, name, value) VALUES (1, 'c', 42)")));
        }
    }
    db::Database database(dir / "records.sqlite");
    QSqlDatabase c = database.connection();
    EXPECT_EQ(db::schemaVersion(c), db::latestSchemaVersion());
    QSqlQuery query(c);
    ASSERT_TRUE(query.exec(QStringLiteral("SELECT count(*) FROM scores WHERE value = 42")) && query.next());
    EXPECT_EQ(query.value(0).toInt(), start >= 1 ? 1 : 0);
    ASSERT_TRUE(
        query.exec(QStringLiteral("SELECT count(*) FROM sqlite_master WHERE name = 'sessions_by_user'")) &&
        query.next());
    EXPECT_EQ(query.value(0).toInt(), 1);
    // Migration 5 stores the shipped core rule set as version 1, active, once.
    ASSERT_TRUE(
        query.exec(QStringLiteral("SELECT count(*), min(version), min(active), min(imported_by IS NULL) "
                                  "FROM certification_rule_sets")) &&
        query.next());
    EXPECT_EQ(query.value(0).toInt(), 1);
    EXPECT_EQ(query.value(1).toInt(), 1);
    EXPECT_EQ(query.value(2).toInt(), 1);
    EXPECT_EQ(query.value(3).toInt(), 1);
}

INSTANTIATE_TEST_SUITE_P(EveryVersion, FromEarlierVersion, ::testing::Range(0, db::latestSchemaVersion()));

TEST(Migrations, ANewerFileIsRefused)
{
    test::TempDir dir;
    {
        RawConnection raw(dir / "records.sqlite");
        ASSERT_TRUE(raw.exec(QStringLiteral("PRAGMA user_version = %1").arg(db::latestSchemaVersion() + 1)));
    }
    try {
        db::Database database(dir / "records.sqlite");
        FAIL() << "a newer schema was opened";
    } catch (const db::DatabaseError& error) {
        EXPECT_NE(std::string(error.what()).find("newer than this build"), std::string::npos) << error.what();
    }
}

TEST(AuditLog, RecordsChangesAndRefusesUpdateAndDelete)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("root", "correct horse battery");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
    records.setPassword(admin, "ada", "ada-password-2");
    const auto log = records.audit(admin);
    ASSERT_EQ(log.size(), 4u);
    // The migration stored the shipped certification rule set; then the users.
    EXPECT_EQ(log[0].table, "certification_rule_sets");
    EXPECT_EQ(log[0].actor, "(system)");
    EXPECT_EQ(log[1].actor, "(system)");
    EXPECT_EQ(log[2].actor, "root");
    EXPECT_EQ(log[2].detail, "ada student");
    EXPECT_EQ(log[3].action, "update");
    EXPECT_NE(log[3].detail.find("password changed"), std::string::npos);
    QSqlQuery query(database.connection());
    EXPECT_FALSE(query.exec(QStringLiteral("UPDATE audit SET detail = 'forged'")));
    EXPECT_NE(query.lastError().text().toStdString().find("append-only"), std::string::npos);
    EXPECT_FALSE(query.exec(QStringLiteral("DELETE FROM audit")));
    EXPECT_EQ(records.audit(admin).size(), 4u);
}

TEST(AuditLog, RecordsScoresProgressAndCertificatesWithTheirActor)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("root", "correct horse battery");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
    const db::Actor ada = records.authenticate("ada", "ada-password");
    const size_t before = records.audit(admin).size();

    // A session stored with its score and the progress it made.
    const qint64 session = records.beginSession(ada, std::nullopt, "navigation-straight", "keyboard");
    db::SessionResult result;
    result.duration = 1.0;
    result.scores = {{"composite", 71.5}};
    result.curriculum = "colonoscopy-core";
    result.progress = {{"navigation-straight", "proficient"}};
    records.completeSession(ada, session, result);
    // Re-scored by the administrator, then a certificate issued.
    const qint64 set = records.storeBenchmarkSet(admin, "core-navigation", 1, "{}");
    records.rescore(admin, session, {{"composite", 80.0}}, set);
    records.issueCertificate(admin, "ada", std::string(64, 'a'), "signature", "public-key");
    // A progress row deleted outside the layer (which never deletes one) leaves a trace too.
    {
        QSqlQuery query(database.connection());
        ASSERT_TRUE(query.exec(QStringLiteral("DELETE FROM progress")));
    }

    const auto log = records.audit(admin);
    ASSERT_GT(log.size(), before);
    std::vector<std::string> seen;
    for (size_t k = before; k < log.size(); ++k) {
        seen.push_back(log[k].table + " " + log[k].action + " by " + log[k].actor + ": " + log[k].detail);
    }
    const auto has = [&](const std::string& line) {
        return std::find(seen.begin(), seen.end(), line) != seen.end();
    };
    const std::string s = std::to_string(session);
    EXPECT_TRUE(has("scores insert by ada: session " + s + " composite=71.5"))
        << ::testing::PrintToString(seen);
    EXPECT_TRUE(has("progress insert by ada: navigation-straight proficient"))
        << ::testing::PrintToString(seen);
    bool rescored = false;
    bool certified = false;
    bool progressDeleted = false;
    for (size_t k = before; k < log.size(); ++k) {
        const db::AuditRow& row = log[k];
        rescored = rescored || (row.table == "scores" && row.actor == "root" &&
                                row.detail.find("composite") != std::string::npos &&
                                row.detail.find("80") != std::string::npos);
        certified =
            certified || (row.table == "certificates" && row.action == "insert" && row.actor == "root");
        progressDeleted = progressDeleted || (row.table == "progress" && row.action == "delete" &&
                                              row.detail == "navigation-straight proficient");
    }
    EXPECT_TRUE(rescored) << ::testing::PrintToString(seen);
    EXPECT_TRUE(certified) << ::testing::PrintToString(seen);
    EXPECT_TRUE(progressDeleted) << ::testing::PrintToString(seen);
}

TEST(Passwords, AreStoredAsArgon2idAndVerified)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    db::Records records(database);
    records.bootstrapAdministrator("root", "correct horse battery");
    QSqlQuery query(database.connection());
    ASSERT_TRUE(query.exec(QStringLiteral("SELECT password_hash FROM users")) && query.next());
    EXPECT_TRUE(query.value(0).toString().startsWith(QStringLiteral("$argon2id$")));
    EXPECT_NO_THROW((void)records.authenticate("root", "correct horse battery"));
    EXPECT_THROW((void)records.authenticate("root", "wrong password"), db::AuthenticationFailed);
    EXPECT_THROW((void)records.authenticate("nobody", "correct horse battery"), db::AuthenticationFailed);
    EXPECT_THROW(records.bootstrapAdministrator("second", "another password"), db::AccessDenied);
}

}  // namespace
