// kill -9 of a real process writing sessions to a real file: the file stays
// consistent (PRAGMA integrity_check is "ok"), the interrupted session is
// marked aborted on the next open and never counts, no completed session is lost.
#include "db/Database.h"
#include "db/Records.h"
#include "tests/db/TempDir.h"

#include <QSqlQuery>

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace colonosim;

class Child {
public:
    Child(const std::filesystem::path& db, bool hang)
    {
        int fds[2];
        EXPECT_EQ(::pipe(fds), 0);
        m_pid = ::fork();
        if (m_pid == 0) {
            ::dup2(fds[1], STDOUT_FILENO);
            ::close(fds[0]);
            const std::string path = db.string();
            if (hang) {
                ::execl(COLONOSIM_SESSION_WRITER, COLONOSIM_SESSION_WRITER, path.c_str(), "--hang", nullptr);
            } else {
                ::execl(COLONOSIM_SESSION_WRITER, COLONOSIM_SESSION_WRITER, path.c_str(), nullptr);
            }
            ::_exit(127);
        }
        ::close(fds[1]);
        m_out = ::fdopen(fds[0], "r");
    }
    ~Child()
    {
        if (m_pid > 0) {
            kill9();
        }
        if (m_out) {
            std::fclose(m_out);
        }
    }
    /// The next line of the child's output ("" at end of file).
    std::string line()
    {
        char buffer[256];
        return std::fgets(buffer, sizeof(buffer), m_out) ? std::string(buffer) : std::string();
    }
    void kill9()
    {
        ::kill(m_pid, SIGKILL);
        int status = 0;
        ::waitpid(m_pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status));
        m_pid = -1;
    }

private:
    pid_t m_pid = -1;
    FILE* m_out = nullptr;
};

void seed(const std::filesystem::path& path)
{
    db::Database database(path);
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("root", "root-password");
    records.addUser(admin, "ada", db::Role::Student, "ada-password");
}

long long scalar(db::Database& database, const QString& sql)
{
    QSqlQuery query(database.connection());
    EXPECT_TRUE(query.exec(sql) && query.next()) << sql.toStdString();
    return query.value(0).toLongLong();
}

TEST(CrashSafety, KillDuringTheFinalTransactionLeavesAConsistentFile)
{
    test::TempDir dir;
    const auto path = dir / "records.sqlite";
    seed(path);
    long long interrupted = 0;
    {
        Child child(path, true);
        for (int n = 1; n <= 3; ++n) {
            EXPECT_EQ(child.line(), "completed " + std::to_string(n) + "\n");
        }
        const std::string mid = child.line();
        ASSERT_EQ(mid.rfind("mid-transaction ", 0), 0u) << mid;
        interrupted = std::stoll(mid.substr(16));
        child.kill9();
    }
    db::Database database(path);
    EXPECT_EQ(database.abortedOnOpen(), 1);
    QSqlQuery check(database.connection());
    ASSERT_TRUE(check.exec(QStringLiteral("PRAGMA integrity_check")) && check.next());
    EXPECT_EQ(check.value(0).toString(), QStringLiteral("ok"));
    EXPECT_EQ(scalar(database, QStringLiteral("SELECT count(*) FROM sessions WHERE status = 'completed'")),
              3);
    EXPECT_EQ(
        scalar(database,
               QStringLiteral("SELECT status = 'aborted' FROM sessions WHERE id = %1").arg(interrupted)),
        1);
    // The half-written events of the interrupted transaction are gone.
    EXPECT_EQ(scalar(database,
                     QStringLiteral("SELECT count(*) FROM events WHERE session_id = %1").arg(interrupted)),
              0);
    db::Records records(database);
    const db::Actor ada = records.authenticate("ada", "ada-password");
    EXPECT_EQ(records.sessions(ada, "ada").size(), 3u);
    EXPECT_EQ(records.learningCurve(ada, "ada", "total_time").size(), 3u);
}

TEST(CrashSafety, KillWhileWritingFreelyLosesNoCompletedSession)
{
    test::TempDir dir;
    const auto path = dir / "records.sqlite";
    seed(path);
    int reported = 0;
    {
        Child child(path, false);
        while (reported < 5) {
            const std::string line = child.line();
            ASSERT_FALSE(line.empty()) << "the writer stopped early";
            reported = std::stoi(line.substr(10));
        }
        child.kill9();
    }
    db::Database database(path);
    QSqlQuery check(database.connection());
    ASSERT_TRUE(check.exec(QStringLiteral("PRAGMA integrity_check")) && check.next());
    EXPECT_EQ(check.value(0).toString(), QStringLiteral("ok"));
    EXPECT_EQ(scalar(database, QStringLiteral("SELECT count(*) FROM sessions WHERE status = 'running'")), 0);
    EXPECT_GE(scalar(database, QStringLiteral("SELECT count(*) FROM sessions WHERE status = 'completed'")),
              reported);
    // Every completed session is whole: its metrics and its 50 events are there.
    EXPECT_EQ(
        scalar(database, QStringLiteral("SELECT count(*) FROM sessions s WHERE status = 'completed' AND "
                                        "(SELECT count(*) FROM events e WHERE e.session_id = s.id) <> 50")),
        0);
    EXPECT_EQ(scalar(database, QStringLiteral("SELECT count(*) FROM sessions s WHERE status = 'aborted' AND "
                                              "EXISTS (SELECT 1 FROM metrics m WHERE m.session_id = s.id)")),
              0);
}

}  // namespace
