#pragma once
/// \file
/// The data-access layer: every read and write of the records goes through
/// here, and authorization is enforced here, not in the user interface.
///
///   student        reads only their own records; runs sessions for themselves;
///                  changes their own password
///   instructor     as a student, and reads the records of the students of the
///                  cohorts they are assigned to
///   administrator  reads everything; the only role that manages users,
///                  cohorts, curricula, benchmark sets and certificates,
///                  reads the audit log and takes backups
/// A refused operation throws AccessDenied naming the actor, their role, the
/// operation and the rule. Every write runs in one transaction that first
/// names the actor, so the audit triggers record who changed what.
///
/// A session is inserted as `running` (beginSession) and finalised in one
/// transaction with its trace, recording, events, metrics, scores and
/// progress (completeSession). Only completed sessions are read as results.

#include "db/Database.h"

#include <QByteArray>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace colonosim::db {

enum class Role { Student, Instructor, Administrator };
[[nodiscard]] std::string roleName(Role role);
/// Throws DatabaseError naming the value and the allowed ones.
[[nodiscard]] Role parseRole(const std::string& name);

struct Actor {
    qint64 id = 0;
    std::string name;
    Role role = Role::Student;
};

class AccessDenied : public std::runtime_error {
public:
    explicit AccessDenied(const std::string& message) : std::runtime_error(message) {}
};

/// AccessDenied naming the actor, their role and `operation` unless `actor` is an administrator.
void requireAdministrator(const Actor& actor, const std::string& operation);

class AuthenticationFailed : public std::runtime_error {
public:
    explicit AuthenticationFailed(const std::string& message) : std::runtime_error(message) {}
};

struct UserRow {
    qint64 id;
    std::string name;
    Role role;
    std::string createdAt;
};

struct SessionResult {
    QByteArray trace;       ///< encodeTrace()
    QByteArray recording;   ///< encodeRecording()
    double duration = 0.0;  ///< s simulated
    struct Event {
        double time;
        std::string kind, detail;
    };
    std::vector<Event> events;
    std::map<std::string, double> metrics;
    std::map<std::string, double> scores;
    std::optional<qint64> benchmarkSetId;
    std::string curriculum;
    std::map<std::string, std::string> progress;  ///< task -> state, for the session's user
};

struct SessionRow {
    qint64 id;
    std::string user, task, device, status, startedAt;
    double duration;
    std::map<std::string, double> metrics;
    std::map<std::string, double> scores;
};

struct CurvePoint {
    qint64 session;
    double value;
};

struct CertificateRow {
    qint64 id;
    std::string user, issuedBy, issuedAt, contentSha256, signature, publicKey;
};

struct AuditRow {
    qint64 id;
    std::string at, actor, table, action, detail;
    qint64 row;
};

class Records {
public:
    explicit Records(Database& database) : m_database(database) {}

    /// Throws AuthenticationFailed (the same message for an unknown name and a wrong password).
    [[nodiscard]] Actor authenticate(const std::string& name, const std::string& password);
    /// True when the database has no user yet (first start).
    [[nodiscard]] bool empty();
    /// First start only: creates the first administrator; refused once any user exists.
    Actor bootstrapAdministrator(const std::string& name, const std::string& password);

    qint64 addUser(const Actor& actor, const std::string& name, Role role, const std::string& password);
    [[nodiscard]] std::vector<UserRow> listUsers(const Actor& actor);
    void setPassword(const Actor& actor, const std::string& name, const std::string& password);

    qint64 addCohort(const Actor& actor, const std::string& name);
    void addMember(const Actor& actor, const std::string& cohort, const std::string& user);
    void assignInstructor(const Actor& actor, const std::string& cohort, const std::string& instructor);

    qint64 storeCase(const Actor& actor, const std::string& name, const std::string& xml);
    void storeCurriculum(const Actor& actor, const std::string& name, const std::string& xml);
    [[nodiscard]] std::optional<std::string> curriculum(const Actor& actor, const std::string& name);
    qint64 storeBenchmarkSet(const Actor& actor, const std::string& name, int version,
                             const std::string& json);
    /// The newest version of a benchmark set: (id, version, json).
    [[nodiscard]] std::optional<std::tuple<qint64, int, std::string>>
    latestBenchmarkSet(const std::string& name);

    qint64 beginSession(const Actor& actor, std::optional<qint64> caseId, const std::string& task,
                        const std::string& device);
    void completeSession(const Actor& actor, qint64 session, const SessionResult& result);
    /// Completed sessions of `user`, oldest first, with metrics and scores.
    [[nodiscard]] std::vector<SessionRow> sessions(const Actor& actor, const std::string& user);
    [[nodiscard]] QByteArray sessionRecording(const Actor& actor, qint64 session);
    /// The stored input trace of a session (encodeStoredTrace), for replay;
    /// readable by whoever may read its recording.
    [[nodiscard]] QByteArray sessionTrace(const Actor& actor, qint64 session);
    /// The case XML a session ran on (none: the default colon); same rule as sessionTrace.
    [[nodiscard]] std::optional<std::string> sessionCase(const Actor& actor, qint64 session);
    /// One metric of one trainee across their completed sessions (the dashboard query).
    [[nodiscard]] std::vector<CurvePoint> learningCurve(const Actor& actor, const std::string& user,
                                                        const std::string& metric);
    /// Replaces a session's scores after a benchmark set changed (administrators).
    void rescore(const Actor& actor, qint64 session, const std::map<std::string, double>& scores,
                 qint64 benchmarkSetId);

    [[nodiscard]] std::map<std::string, std::string> progress(const Actor& actor, const std::string& user,
                                                              const std::string& curriculum);

    qint64 issueCertificate(const Actor& actor, const std::string& user, const std::string& contentSha256,
                            const std::string& signature, const std::string& publicKey);
    /// Public: the record a certificate file is verified against (no secret in it).
    [[nodiscard]] std::optional<CertificateRow> certificateBySha(const std::string& contentSha256);

    [[nodiscard]] std::vector<AuditRow> audit(const Actor& actor);
    void backup(const Actor& actor, const std::filesystem::path& destination);

private:
    enum class SessionBlob { Recording, Trace };
    /// One stored column of a session, read under requireReadable.
    [[nodiscard]] QByteArray sessionBlob(const Actor& actor, qint64 session, SessionBlob which);
    [[nodiscard]] qint64 userId(const std::string& name);
    [[nodiscard]] qint64 cohortId(const std::string& name);
    void requireReadable(const Actor& actor, qint64 user, const std::string& userName);

    Database& m_database;
};

}  // namespace colonosim::db
