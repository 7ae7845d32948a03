#include "db/Records.h"

#include "db/Password.h"
#include "db/Statement.h"

#include <QCryptographicHash>
#include <QSqlError>
#include <QSqlQuery>
#include <QVariant>

namespace colonosim::db {

namespace {

QString q(const std::string& s)
{
    return QString::fromStdString(s);
}

std::string s(const QVariant& v)
{
    return v.toString().toStdString();
}

QSqlQuery run(QSqlDatabase db, const QString& sql, const QVariantList& binds = {})
{
    return runStatement(std::move(db), sql, binds);
}

void checkName(const std::string& field, const std::string& value)
{
    if (value.empty() || value.size() > 64) {
        throw DatabaseError(field + " \"" + value + "\" must be 1-64 characters");
    }
}

}  // namespace

std::string roleName(Role role)
{
    switch (role) {
    case Role::Student: return "student";
    case Role::Instructor: return "instructor";
    case Role::Administrator: return "administrator";
    }
    return "student";
}

Role parseRole(const std::string& name)
{
    if (name == "student") {
        return Role::Student;
    }
    if (name == "instructor") {
        return Role::Instructor;
    }
    if (name == "administrator") {
        return Role::Administrator;
    }
    throw DatabaseError("role \"" + name + "\" is not one of student, instructor, administrator");
}

qint64 Records::userId(const std::string& name)
{
    QSqlQuery query =
        run(m_database.connection(), QStringLiteral("SELECT id FROM users WHERE name = ?"), {q(name)});
    if (!query.next()) {
        throw DatabaseError("user \"" + name + "\" does not exist");
    }
    return query.value(0).toLongLong();
}

qint64 Records::cohortId(const std::string& name)
{
    QSqlQuery query =
        run(m_database.connection(), QStringLiteral("SELECT id FROM cohorts WHERE name = ?"), {q(name)});
    if (!query.next()) {
        throw DatabaseError("cohort \"" + name + "\" does not exist");
    }
    return query.value(0).toLongLong();
}

void requireAdministrator(const Actor& actor, const std::string& operation)
{
    if (actor.role != Role::Administrator) {
        throw AccessDenied(actor.name + " (" + roleName(actor.role) + ") may not " + operation +
                           ": only administrators may");
    }
}

void Records::requireReadable(const Actor& actor, qint64 user, const std::string& userName)
{
    if (actor.role == Role::Administrator || actor.id == user) {
        return;
    }
    if (actor.role == Role::Instructor) {
        QSqlQuery query =
            run(m_database.connection(),
                QStringLiteral("SELECT 1 FROM cohort_members m JOIN cohort_instructors i "
                               "ON i.cohort_id = m.cohort_id WHERE m.user_id = ? AND i.user_id = ?"),
                {user, actor.id});
        if (query.next()) {
            return;
        }
        throw AccessDenied(actor.name + " (instructor) may not read the records of " + userName +
                           ": an instructor reads only the students of their cohorts");
    }
    throw AccessDenied(actor.name + " (" + roleName(actor.role) + ") may not read the records of " +
                       userName + ": a student reads only their own records");
}

Actor Records::authenticate(const std::string& name, const std::string& password)
{
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT id, role, password_hash FROM users WHERE name = ?"), {q(name)});
    if (!query.next() || !verifyPassword(s(query.value(2)), password)) {
        throw AuthenticationFailed("authentication failed for user \"" + name + "\"");
    }
    return Actor{query.value(0).toLongLong(), name, parseRole(s(query.value(1)))};
}

bool Records::empty()
{
    QSqlQuery query = run(m_database.connection(), QStringLiteral("SELECT count(*) FROM users"));
    query.next();
    return query.value(0).toLongLong() == 0;
}

Actor Records::bootstrapAdministrator(const std::string& name, const std::string& password)
{
    checkName("user name", name);
    const std::string hash = hashPassword(password);
    WriteTransaction tx(m_database.connection(), std::nullopt);
    QSqlQuery count = run(m_database.connection(), QStringLiteral("SELECT count(*) FROM users"));
    count.next();
    if (count.value(0).toLongLong() != 0) {
        throw AccessDenied("the first administrator exists already; ask an administrator to add users");
    }
    QSqlQuery insert = run(m_database.connection(),
                           QStringLiteral("INSERT INTO users (name, role, password_hash) VALUES (?, ?, ?)"),
                           {q(name), QStringLiteral("administrator"), q(hash)});
    const qint64 id = insert.lastInsertId().toLongLong();
    tx.commit();
    return Actor{id, name, Role::Administrator};
}

qint64 Records::addUser(const Actor& actor, const std::string& name, Role role, const std::string& password)
{
    requireAdministrator(actor, "add users");
    checkName("user name", name);
    const std::string hash = hashPassword(password);
    WriteTransaction tx(m_database.connection(), actor.id);
    QSqlQuery exists =
        run(m_database.connection(), QStringLiteral("SELECT 1 FROM users WHERE name = ?"), {q(name)});
    if (exists.next()) {
        throw DatabaseError("user \"" + name + "\" exists already");
    }
    QSqlQuery insert = run(m_database.connection(),
                           QStringLiteral("INSERT INTO users (name, role, password_hash) VALUES (?, ?, ?)"),
                           {q(name), q(roleName(role)), q(hash)});
    const qint64 id = insert.lastInsertId().toLongLong();
    tx.commit();
    return id;
}

std::vector<UserRow> Records::listUsers(const Actor& actor)
{
    QString sql = QStringLiteral("SELECT id, name, role, created_at FROM users");
    QVariantList binds;
    if (actor.role == Role::Student) {
        sql += QStringLiteral(" WHERE id = ?");
        binds = {actor.id};
    } else if (actor.role == Role::Instructor) {
        sql += QStringLiteral(" WHERE id = ? OR id IN (SELECT m.user_id FROM cohort_members m JOIN "
                              "cohort_instructors i ON i.cohort_id = m.cohort_id WHERE i.user_id = ?)");
        binds = {actor.id, actor.id};
    }
    sql += QStringLiteral(" ORDER BY name");
    QSqlQuery query = run(m_database.connection(), sql, binds);
    std::vector<UserRow> out;
    while (query.next()) {
        out.push_back({query.value(0).toLongLong(), s(query.value(1)), parseRole(s(query.value(2))),
                       s(query.value(3))});
    }
    return out;
}

void Records::setPassword(const Actor& actor, const std::string& name, const std::string& password)
{
    if (actor.name != name) {
        requireAdministrator(actor, "change the password of another user (" + name + ")");
    }
    const std::string hash = hashPassword(password);
    const qint64 id = userId(name);
    WriteTransaction tx(m_database.connection(), actor.id);
    run(m_database.connection(), QStringLiteral("UPDATE users SET password_hash = ? WHERE id = ?"),
        {q(hash), id});
    tx.commit();
}

qint64 Records::addCohort(const Actor& actor, const std::string& name)
{
    requireAdministrator(actor, "add cohorts");
    checkName("cohort name", name);
    WriteTransaction tx(m_database.connection(), actor.id);
    QSqlQuery insert =
        run(m_database.connection(), QStringLiteral("INSERT INTO cohorts (name) VALUES (?)"), {q(name)});
    const qint64 id = insert.lastInsertId().toLongLong();
    tx.commit();
    return id;
}

void Records::addMember(const Actor& actor, const std::string& cohort, const std::string& user)
{
    requireAdministrator(actor, "manage cohorts");
    const qint64 member = userId(user);
    const qint64 group = cohortId(cohort);
    WriteTransaction tx(m_database.connection(), actor.id);
    run(m_database.connection(),
        QStringLiteral("INSERT OR IGNORE INTO cohort_members (cohort_id, user_id) VALUES (?, ?)"),
        {group, member});
    tx.commit();
}

void Records::assignInstructor(const Actor& actor, const std::string& cohort, const std::string& instructor)
{
    requireAdministrator(actor, "assign instructors");
    const qint64 id = userId(instructor);
    QSqlQuery role =
        run(m_database.connection(), QStringLiteral("SELECT role FROM users WHERE id = ?"), {id});
    role.next();
    if (s(role.value(0)) != "instructor") {
        throw DatabaseError("user \"" + instructor + "\" has role " + s(role.value(0)) +
                            "; only an instructor can be assigned to a cohort");
    }
    const qint64 group = cohortId(cohort);
    WriteTransaction tx(m_database.connection(), actor.id);
    run(m_database.connection(),
        QStringLiteral("INSERT OR IGNORE INTO cohort_instructors (cohort_id, user_id) VALUES (?, ?)"),
        {group, id});
    tx.commit();
}

qint64 Records::storeCase(const Actor& actor, const std::string& name, const std::string& xml)
{
    const QString hash = QString::fromLatin1(
        QCryptographicHash::hash(QByteArray::fromStdString(xml), QCryptographicHash::Sha256).toHex());
    WriteTransaction tx(m_database.connection(), actor.id);
    run(m_database.connection(),
        QStringLiteral("INSERT OR IGNORE INTO cases (name, xml, sha256) VALUES (?, ?, ?)"),
        {q(name), q(xml), hash});
    QSqlQuery id =
        run(m_database.connection(), QStringLiteral("SELECT id FROM cases WHERE sha256 = ?"), {hash});
    id.next();
    const qint64 out = id.value(0).toLongLong();
    tx.commit();
    return out;
}

void Records::storeCurriculum(const Actor& actor, const std::string& name, const std::string& xml)
{
    requireAdministrator(actor, "manage curricula");
    WriteTransaction tx(m_database.connection(), actor.id);
    run(m_database.connection(),
        QStringLiteral(
            "INSERT INTO curricula (name, xml) VALUES (?, ?) ON CONFLICT (name) DO UPDATE SET xml = "
            "excluded.xml"),
        {q(name), q(xml)});
    tx.commit();
}

std::optional<std::string> Records::curriculum(const Actor&, const std::string& name)
{
    QSqlQuery query =
        run(m_database.connection(), QStringLiteral("SELECT xml FROM curricula WHERE name = ?"), {q(name)});
    if (!query.next()) {
        return std::nullopt;
    }
    return s(query.value(0));
}

qint64 Records::storeBenchmarkSet(const Actor& actor, const std::string& name, int version,
                                  const std::string& json)
{
    requireAdministrator(actor, "manage benchmark sets");
    WriteTransaction tx(m_database.connection(), actor.id);
    QSqlQuery insert =
        run(m_database.connection(),
            QStringLiteral("INSERT INTO benchmark_sets (name, version, json) VALUES (?, ?, ?)"),
            {q(name), version, q(json)});
    const qint64 id = insert.lastInsertId().toLongLong();
    tx.commit();
    return id;
}

std::optional<std::tuple<qint64, int, std::string>> Records::latestBenchmarkSet(const std::string& name)
{
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT id, version, json FROM benchmark_sets WHERE name = ? ORDER BY "
                           "version DESC LIMIT 1"),
            {q(name)});
    if (!query.next()) {
        return std::nullopt;
    }
    return std::tuple{query.value(0).toLongLong(), query.value(1).toInt(), s(query.value(2))};
}

qint64 Records::beginSession(const Actor& actor, std::optional<qint64> caseId, const std::string& task,
                             const std::string& device)
{
    WriteTransaction tx(m_database.connection(), actor.id);
    QSqlQuery insert =
        run(m_database.connection(),
            QStringLiteral(
                "INSERT INTO sessions (user_id, case_id, task, device, owner, status) VALUES (?, ?, ?, ?, ?, "
                "'running')"),
            {actor.id, caseId ? QVariant(*caseId) : QVariant(), q(task), q(device), Database::ownerTag()});
    const qint64 id = insert.lastInsertId().toLongLong();
    tx.commit();
    return id;
}

void Records::completeSession(const Actor& actor, qint64 session, const SessionResult& result)
{
    QSqlDatabase db = m_database.connection();
    WriteTransaction tx(db, actor.id);
    QSqlQuery owner = run(db, QStringLiteral("SELECT user_id, status FROM sessions WHERE id = ?"), {session});
    if (!owner.next()) {
        throw DatabaseError("session " + std::to_string(session) + " does not exist");
    }
    if (owner.value(0).toLongLong() != actor.id) {
        throw AccessDenied(actor.name + " may not complete session " + std::to_string(session) +
                           ": a session is completed only by the user who runs it");
    }
    if (s(owner.value(1)) != "running") {
        throw DatabaseError("session " + std::to_string(session) + " is " + s(owner.value(1)) +
                            ", not running: it cannot be completed");
    }
    run(db,
        QStringLiteral(
            "UPDATE sessions SET status = 'completed', finished_at = strftime('%Y-%m-%dT%H:%M:%fZ', "
            "'now'), duration_s = ?, trace = ?, recording = ? WHERE id = ?"),
        {result.duration, result.trace, result.recording, session});
    QSqlQuery events(db);
    events.prepare(
        QStringLiteral("INSERT INTO events (session_id, seq, time_s, kind, detail) VALUES (?, ?, ?, ?, ?)"));
    int seq = 0;
    for (const auto& e : result.events) {
        events.addBindValue(session);
        events.addBindValue(seq++);
        events.addBindValue(e.time);
        events.addBindValue(q(e.kind));
        events.addBindValue(q(e.detail));
        if (!events.exec()) {
            throw DatabaseError("cannot store event: " + events.lastError().text().toStdString());
        }
    }
    QSqlQuery metrics(db);
    metrics.prepare(QStringLiteral("INSERT INTO metrics (session_id, name, value) VALUES (?, ?, ?)"));
    for (const auto& [name, value] : result.metrics) {
        metrics.addBindValue(session);
        metrics.addBindValue(q(name));
        metrics.addBindValue(value);
        if (!metrics.exec()) {
            throw DatabaseError("cannot store metric " + name + ": " +
                                metrics.lastError().text().toStdString());
        }
    }
    for (const auto& [name, value] : result.scores) {
        run(db,
            QStringLiteral(
                "INSERT INTO scores (session_id, name, value, benchmark_set_id) VALUES (?, ?, ?, ?)"),
            {session, q(name), value, result.benchmarkSetId ? QVariant(*result.benchmarkSetId) : QVariant()});
    }
    for (const auto& [task, state] : result.progress) {
        run(db,
            QStringLiteral(
                "INSERT INTO progress (user_id, curriculum, task, state) VALUES (?, ?, ?, ?) ON CONFLICT "
                "(user_id, curriculum, task) DO UPDATE SET state = excluded.state, updated_at = "
                "excluded.updated_at WHERE state <> excluded.state"),
            {actor.id, q(result.curriculum), q(task), q(state)});
    }
    tx.commit();
}

std::vector<SessionRow> Records::sessions(const Actor& actor, const std::string& user)
{
    const qint64 id = userId(user);
    requireReadable(actor, id, user);
    QSqlDatabase db = m_database.connection();
    QSqlQuery query =
        run(db,
            QStringLiteral("SELECT id, task, device, status, started_at, duration_s FROM sessions "
                           "WHERE user_id = ? AND status = 'completed' ORDER BY id"),
            {id});
    std::vector<SessionRow> out;
    std::map<qint64, size_t> index;
    while (query.next()) {
        index[query.value(0).toLongLong()] = out.size();
        out.push_back({query.value(0).toLongLong(),
                       user,
                       s(query.value(1)),
                       s(query.value(2)),
                       s(query.value(3)),
                       s(query.value(4)),
                       query.value(5).toDouble(),
                       {},
                       {}});
    }
    QSqlQuery metrics =
        run(db,
            QStringLiteral("SELECT m.session_id, m.name, m.value FROM metrics m JOIN sessions s ON "
                           "s.id = m.session_id WHERE s.user_id = ? AND s.status = 'completed'"),
            {id});
    while (metrics.next()) {
        out[index.at(metrics.value(0).toLongLong())].metrics[s(metrics.value(1))] =
            metrics.value(2).toDouble();
    }
    QSqlQuery scores =
        run(db,
            QStringLiteral("SELECT c.session_id, c.name, c.value FROM scores c JOIN sessions s ON "
                           "s.id = c.session_id WHERE s.user_id = ? AND s.status = 'completed'"),
            {id});
    while (scores.next()) {
        out[index.at(scores.value(0).toLongLong())].scores[s(scores.value(1))] = scores.value(2).toDouble();
    }
    return out;
}

QByteArray Records::sessionBlob(const Actor& actor, qint64 session, SessionBlob which)
{
    const QString column =
        which == SessionBlob::Recording ? QStringLiteral("recording") : QStringLiteral("trace");
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT s.user_id, u.name, s.") + column +
                QStringLiteral(" FROM sessions s JOIN users u ON u.id = s.user_id WHERE s.id = ?"),
            {session});
    if (!query.next()) {
        throw DatabaseError("session " + std::to_string(session) + " does not exist");
    }
    requireReadable(actor, query.value(0).toLongLong(), s(query.value(1)));
    return query.value(2).toByteArray();
}

QByteArray Records::sessionRecording(const Actor& actor, qint64 session)
{
    return sessionBlob(actor, session, SessionBlob::Recording);
}

QByteArray Records::sessionTrace(const Actor& actor, qint64 session)
{
    return sessionBlob(actor, session, SessionBlob::Trace);
}

std::optional<std::string> Records::sessionCase(const Actor& actor, qint64 session)
{
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT s.user_id, u.name, c.xml FROM sessions s JOIN users u ON u.id = "
                           "s.user_id LEFT JOIN cases c ON c.id = s.case_id WHERE s.id = ?"),
            {session});
    if (!query.next()) {
        throw DatabaseError("session " + std::to_string(session) + " does not exist");
    }
    requireReadable(actor, query.value(0).toLongLong(), s(query.value(1)));
    if (query.value(2).isNull()) {
        return std::nullopt;
    }
    return s(query.value(2));
}

std::vector<CurvePoint> Records::learningCurve(const Actor& actor, const std::string& user,
                                               const std::string& metric)
{
    const qint64 id = userId(user);
    requireReadable(actor, id, user);
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT s.id, m.value FROM sessions s JOIN metrics m ON m.session_id = s.id "
                           "AND m.name = ? WHERE s.user_id = ? AND s.status = 'completed' ORDER BY s.id"),
            {q(metric), id});
    std::vector<CurvePoint> out;
    while (query.next()) {
        out.push_back({query.value(0).toLongLong(), query.value(1).toDouble()});
    }
    return out;
}

void Records::rescore(const Actor& actor, qint64 session, const std::map<std::string, double>& scores,
                      qint64 benchmarkSetId)
{
    requireAdministrator(actor, "re-score sessions");
    WriteTransaction tx(m_database.connection(), actor.id);
    for (const auto& [name, value] : scores) {
        run(m_database.connection(),
            QStringLiteral(
                "INSERT INTO scores (session_id, name, value, benchmark_set_id) VALUES (?, ?, ?, ?) ON "
                "CONFLICT (session_id, name) DO UPDATE SET value = excluded.value, benchmark_set_id = "
                "excluded.benchmark_set_id"),
            {session, q(name), value, benchmarkSetId});
    }
    tx.commit();
}

std::map<std::string, std::string> Records::progress(const Actor& actor, const std::string& user,
                                                     const std::string& curriculum)
{
    const qint64 id = userId(user);
    requireReadable(actor, id, user);
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT task, state FROM progress WHERE user_id = ? AND curriculum = ?"),
            {id, q(curriculum)});
    std::map<std::string, std::string> out;
    while (query.next()) {
        out[s(query.value(0))] = s(query.value(1));
    }
    return out;
}

qint64 Records::issueCertificate(const Actor& actor, const std::string& user,
                                 const std::string& contentSha256, const std::string& signature,
                                 const std::string& publicKey)
{
    requireAdministrator(actor, "issue certificates");
    const qint64 id = userId(user);
    WriteTransaction tx(m_database.connection(), actor.id);
    QSqlQuery insert =
        run(m_database.connection(),
            QStringLiteral("INSERT INTO certificates (user_id, issued_by, content_sha256, signature, "
                           "public_key) VALUES (?, ?, ?, ?, ?)"),
            {id, actor.id, q(contentSha256), q(signature), q(publicKey)});
    const qint64 out = insert.lastInsertId().toLongLong();
    tx.commit();
    return out;
}

std::optional<CertificateRow> Records::certificateBySha(const std::string& contentSha256)
{
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT c.id, u.name, a.name, c.issued_at, c.content_sha256, c.signature, "
                           "c.public_key FROM certificates c JOIN users u ON u.id = c.user_id JOIN users "
                           "a ON a.id = c.issued_by WHERE c.content_sha256 = ?"),
            {q(contentSha256)});
    if (!query.next()) {
        return std::nullopt;
    }
    return CertificateRow{
        query.value(0).toLongLong(), s(query.value(1)), s(query.value(2)), s(query.value(3)),
        s(query.value(4)),           s(query.value(5)), s(query.value(6))};
}

std::vector<AuditRow> Records::audit(const Actor& actor)
{
    requireAdministrator(actor, "read the audit log");
    QSqlQuery query =
        run(m_database.connection(),
            QStringLiteral("SELECT a.id, a.at, coalesce(u.name, '(system)'), a.table_name, a.action, "
                           "a.detail, a.row_id FROM audit a LEFT JOIN users u ON u.id = a.actor_id ORDER "
                           "BY a.id"));
    std::vector<AuditRow> out;
    while (query.next()) {
        out.push_back({query.value(0).toLongLong(), s(query.value(1)), s(query.value(2)), s(query.value(3)),
                       s(query.value(4)), s(query.value(5)), query.value(6).toLongLong()});
    }
    return out;
}

void Records::backup(const Actor& actor, const std::filesystem::path& destination)
{
    requireAdministrator(actor, "take backups");
    m_database.backupTo(destination);
}

}  // namespace colonosim::db
