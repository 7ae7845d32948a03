#pragma once
/// \file
/// One SQLite file, opened through QtSql's QSQLITE driver. Each thread gets
/// its own named connection (QSqlDatabase connections must not cross
/// threads). Every connection runs with WAL journaling, foreign keys on and
/// a busy timeout; the first open migrates the schema to the latest version
/// and marks stale running sessions aborted (their process is gone: a crash
/// or kill -9), so they never count towards progress or certification.
///
/// A QCoreApplication must exist before a Database is opened (Qt loads the
/// SQL driver as a plugin).

#include "db/Schema.h"

#include <QSqlDatabase>
#include <QString>

#include <filesystem>

namespace colonosim::db {

class Database {
public:
    /// Opens (creating if missing) and migrates. Throws DatabaseError.
    explicit Database(std::filesystem::path path);
    ~Database();
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;

    /// This thread's connection, opened on first use.
    [[nodiscard]] QSqlDatabase connection() const;
    [[nodiscard]] const std::filesystem::path& path() const { return m_path; }
    /// Sessions found running whose owner process no longer exists, now aborted.
    [[nodiscard]] int abortedOnOpen() const { return m_abortedOnOpen; }
    /// "host:pid" of this process, stored with each running session.
    [[nodiscard]] static QString ownerTag();

    /// Online backup through SQLite's backup API: a consistent copy while
    /// other connections keep writing. Throws DatabaseError.
    void backupTo(const std::filesystem::path& destination) const;

private:
    int abortStaleSessions();

    std::filesystem::path m_path;
    QString m_prefix;  ///< connection-name prefix unique to this object
    int m_abortedOnOpen = 0;
};

}  // namespace colonosim::db
