#pragma once
/// \file
/// The database schema as an ordered list of migrations. Migration k takes
/// the schema from version k-1 to version k; the version lives in SQLite's
/// `PRAGMA user_version`, so an empty file is version 0. Each migration runs
/// in its own transaction together with the version bump: a failed migration
/// leaves the file at the previous version.
///
///   1  users, cohorts (members, instructors), cases, curricula, sessions,
///      events, metrics, scores, progress, certificates, the audit log
///      (append-only: triggers refuse UPDATE and DELETE) and the audit
///      triggers on users, scores, progress and certificates
///   2  versioned benchmark sets; a score names the benchmark version it used
///   3  indexes for the per-trainee dashboard queries
///   4  case assignments: a stored case assigned to a trainee or a cohort
///      (audited)
///   5  certification rule sets: name, version, the XML of record, who
///      imported it and when, which one is active (at most one); rows are
///      never changed but for `active`, never deleted; imports and
///      activations audited. The shipped core rule set is stored as
///      version 1, active, imported by no one
///   6  deleting a progress row is audited (inserts and updates were; the
///      layer never deletes one, but a change outside it leaves a trace)

#include <QSqlDatabase>

#include <stdexcept>
#include <string>

namespace colonosim::db {

class DatabaseError : public std::runtime_error {
public:
    explicit DatabaseError(const std::string& message) : std::runtime_error(message) {}
};

/// The version this build writes.
[[nodiscard]] int latestSchemaVersion();
/// `PRAGMA user_version` of an open connection.
[[nodiscard]] int schemaVersion(QSqlDatabase& db);
/// Applies migrations up to `target` (latest by default). Refuses a file
/// newer than this build. Throws DatabaseError naming the failed statement.
void migrate(QSqlDatabase& db, int target = -1);

}  // namespace colonosim::db
