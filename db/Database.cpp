#include "db/Database.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>

#include <sqlite3.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace colonosim::db {

namespace {
std::atomic<int> g_instances{0};

void exec(QSqlDatabase& db, const QString& sql)
{
    QSqlQuery query(db);
    if (!query.exec(sql)) {
        throw DatabaseError(sql.toStdString() + ": " + query.lastError().text().toStdString());
    }
}

bool processAlive(long pid)
{
    return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}
}  // namespace

Database::Database(std::filesystem::path path) : m_path(std::move(path))
{
    m_prefix = QStringLiteral("colonosim-%1-%2-").arg(::getpid()).arg(g_instances.fetch_add(1));
    QSqlDatabase db = connection();
    migrate(db);
    m_abortedOnOpen = abortStaleSessions();
}

Database::~Database()
{
    // Connections of other threads are removed when their names are; Qt warns
    // about connections still in use, so drop our handles first.
    for (const QString& name : QSqlDatabase::connectionNames()) {
        if (name.startsWith(m_prefix)) {
            {
                QSqlDatabase db = QSqlDatabase::database(name, false);
                db.close();
            }
            QSqlDatabase::removeDatabase(name);
        }
    }
}

QString Database::ownerTag()
{
    char host[256] = {};
    ::gethostname(host, sizeof(host) - 1);
    return QStringLiteral("%1:%2").arg(QString::fromUtf8(host)).arg(::getpid());
}

QSqlDatabase Database::connection() const
{
    std::ostringstream id;
    id << std::this_thread::get_id();
    const QString name = m_prefix + QString::fromStdString(id.str());
    if (QSqlDatabase::contains(name)) {
        return QSqlDatabase::database(name);
    }
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
    if (!db.isValid()) {
        throw DatabaseError("the QSQLITE driver is not available (install libqt6sql6-sqlite)");
    }
    db.setDatabaseName(QString::fromStdString(m_path.string()));
    db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000"));
    if (!db.open()) {
        throw DatabaseError(m_path.string() + ": cannot open: " + db.lastError().text().toStdString());
    }
    QSqlQuery query(db);
    if (!query.exec(QStringLiteral("PRAGMA journal_mode = WAL")) || !query.next() ||
        query.value(0).toString() != QStringLiteral("wal")) {
        throw DatabaseError(m_path.string() + ": cannot switch to WAL journaling");
    }
    exec(db, QStringLiteral("PRAGMA foreign_keys = ON"));
    exec(db, QStringLiteral("PRAGMA synchronous = NORMAL"));
    return db;
}

int Database::abortStaleSessions()
{
    QSqlDatabase db = connection();
    QSqlQuery query(db);
    if (!query.exec(QStringLiteral("SELECT id, owner FROM sessions WHERE status = 'running'"))) {
        throw DatabaseError("cannot list running sessions: " + query.lastError().text().toStdString());
    }
    const QString host = ownerTag().section(QLatin1Char(':'), 0, 0);
    QList<qint64> stale;
    while (query.next()) {
        const QString owner = query.value(1).toString();
        const QString ownerHost = owner.section(QLatin1Char(':'), 0, 0);
        const long pid = owner.section(QLatin1Char(':'), 1, 1).toLong();
        // A session of another host cannot be checked here and is left alone.
        if (ownerHost == host && !processAlive(pid)) {
            stale.append(query.value(0).toLongLong());
        }
    }
    for (const qint64 id : stale) {
        QSqlQuery update(db);
        update.prepare(
            QStringLiteral("UPDATE sessions SET status = 'aborted', finished_at = "
                           "strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE id = ? AND status = 'running'"));
        update.addBindValue(id);
        if (!update.exec()) {
            throw DatabaseError("cannot mark session " + std::to_string(id) +
                                " aborted: " + update.lastError().text().toStdString());
        }
    }
    return static_cast<int>(stale.size());
}

void Database::backupTo(const std::filesystem::path& destination) const
{
    sqlite3* source = nullptr;
    sqlite3* target = nullptr;
    auto fail = [&](const std::string& what, sqlite3* handle) {
        const std::string message = what + ": " + (handle ? sqlite3_errmsg(handle) : "out of memory");
        sqlite3_close(source);
        sqlite3_close(target);
        throw DatabaseError(message);
    };
    if (sqlite3_open_v2(m_path.c_str(), &source, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
        fail(m_path.string() + ": cannot open for backup", source);
    }
    sqlite3_busy_timeout(source, 10000);
    if (sqlite3_open_v2(destination.c_str(), &target, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
        SQLITE_OK) {
        fail(destination.string() + ": cannot create", target);
    }
    sqlite3_backup* backup = sqlite3_backup_init(target, "main", source, "main");
    if (!backup) {
        fail(destination.string() + ": cannot start the backup", target);
    }
    int rc = SQLITE_OK;
    // Pages in steps, so writers of the source are not held off for the whole copy;
    // a write in between restarts the copy (SQLite's documented behaviour).
    do {
        rc = sqlite3_backup_step(backup, 256);
        if (rc == SQLITE_BUSY || rc == SQLITE_LOCKED) {
            sqlite3_sleep(10);
        }
    } while (rc == SQLITE_OK || rc == SQLITE_BUSY || rc == SQLITE_LOCKED);
    sqlite3_backup_finish(backup);
    if (rc != SQLITE_DONE) {
        fail(destination.string() + ": backup failed", target);
    }
    sqlite3_close(source);
    sqlite3_close(target);
}

}  // namespace colonosim::db
