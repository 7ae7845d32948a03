#include "db/CaseLibrary.h"

#include "db/Statement.h"

#include <QVariant>

namespace colonosim::db {

namespace {

std::string text(const QVariant& v)
{
    return v.toString().toStdString();
}

std::string who(const Actor& actor)
{
    return actor.name + " (" + roleName(actor.role) + ")";
}

}  // namespace

bool CaseLibrary::assignedTo(qint64 caseId, qint64 user)
{
    QSqlQuery query = runStatement(
        m_database.connection(),
        QStringLiteral("SELECT 1 FROM case_assignments WHERE case_id = ? AND (user_id = ? OR cohort_id IN "
                       "(SELECT cohort_id FROM cohort_members WHERE user_id = ?))"),
        {caseId, user, user});
    return query.next();
}

bool CaseLibrary::teaches(qint64 instructor, qint64 student)
{
    QSqlQuery query = runStatement(m_database.connection(),
                                   QStringLiteral("SELECT 1 FROM cohort_members m JOIN cohort_instructors i "
                                                  "ON i.cohort_id = m.cohort_id WHERE m.user_id = ? AND "
                                                  "i.user_id = ?"),
                                   {student, instructor});
    return query.next();
}

void CaseLibrary::requireCase(qint64 caseId)
{
    QSqlQuery query =
        runStatement(m_database.connection(), QStringLiteral("SELECT 1 FROM cases WHERE id = ?"), {caseId});
    if (!query.next()) {
        throw DatabaseError("case " + std::to_string(caseId) + " does not exist in the case library");
    }
}

std::vector<CaseRow> CaseLibrary::cases(const Actor& actor)
{
    QString sql = QStringLiteral("SELECT id, name FROM cases");
    QVariantList binds;
    if (actor.role == Role::Student) {
        sql += QStringLiteral(" WHERE id IN (SELECT case_id FROM case_assignments WHERE user_id = ? OR "
                              "cohort_id IN (SELECT cohort_id FROM cohort_members WHERE user_id = ?))");
        binds = {actor.id, actor.id};
    }
    sql += QStringLiteral(" ORDER BY id");
    QSqlQuery query = runStatement(m_database.connection(), sql, binds);
    std::vector<CaseRow> out;
    while (query.next()) {
        out.push_back({query.value(0).toLongLong(), text(query.value(1))});
    }
    return out;
}

std::string CaseLibrary::caseXml(const Actor& actor, qint64 caseId)
{
    QSqlQuery query =
        runStatement(m_database.connection(), QStringLiteral("SELECT xml FROM cases WHERE id = ?"), {caseId});
    if (!query.next()) {
        throw DatabaseError("case " + std::to_string(caseId) + " does not exist in the case library");
    }
    if (actor.role == Role::Student && !assignedTo(caseId, actor.id)) {
        throw AccessDenied(who(actor) + " may not read case " + std::to_string(caseId) +
                           ": a student reads only the cases assigned to them");
    }
    return text(query.value(0));
}

qint64 CaseLibrary::assignToTrainee(const Actor& actor, qint64 caseId, const std::string& trainee)
{
    if (actor.role == Role::Student) {
        throw AccessDenied(who(actor) + " may not assign cases: only instructors and administrators may");
    }
    QSqlQuery user =
        runStatement(m_database.connection(), QStringLiteral("SELECT id, role FROM users WHERE name = ?"),
                     {QString::fromStdString(trainee)});
    if (!user.next()) {
        throw DatabaseError("user \"" + trainee + "\" does not exist");
    }
    const qint64 userId = user.value(0).toLongLong();
    if (text(user.value(1)) != "student") {
        throw DatabaseError("user \"" + trainee + "\" has role " + text(user.value(1)) +
                            "; cases are assigned to students only");
    }
    if (actor.role == Role::Instructor && !teaches(actor.id, userId)) {
        throw AccessDenied(who(actor) + " may not assign a case to " + trainee +
                           ": an instructor assigns only to the students of their cohorts");
    }
    requireCase(caseId);
    WriteTransaction tx(m_database.connection(), actor.id);
    runStatement(m_database.connection(),
                 QStringLiteral("INSERT OR IGNORE INTO case_assignments (case_id, user_id, assigned_by) "
                                "VALUES (?, ?, ?)"),
                 {caseId, userId, actor.id});
    QSqlQuery id = runStatement(m_database.connection(),
                                QStringLiteral("SELECT id FROM case_assignments WHERE case_id = ? AND "
                                               "user_id = ?"),
                                {caseId, userId});
    id.next();
    const qint64 out = id.value(0).toLongLong();
    tx.commit();
    return out;
}

qint64 CaseLibrary::assignToCohort(const Actor& actor, qint64 caseId, const std::string& cohort)
{
    if (actor.role == Role::Student) {
        throw AccessDenied(who(actor) + " may not assign cases: only instructors and administrators may");
    }
    QSqlQuery group =
        runStatement(m_database.connection(), QStringLiteral("SELECT id FROM cohorts WHERE name = ?"),
                     {QString::fromStdString(cohort)});
    if (!group.next()) {
        throw DatabaseError("cohort \"" + cohort + "\" does not exist");
    }
    const qint64 cohortId = group.value(0).toLongLong();
    if (actor.role == Role::Instructor) {
        QSqlQuery mine = runStatement(m_database.connection(),
                                      QStringLiteral("SELECT 1 FROM cohort_instructors WHERE cohort_id = ? "
                                                     "AND user_id = ?"),
                                      {cohortId, actor.id});
        if (!mine.next()) {
            throw AccessDenied(who(actor) + " may not assign a case to cohort " + cohort +
                               ": an instructor assigns only to the cohorts they are assigned to");
        }
    }
    requireCase(caseId);
    WriteTransaction tx(m_database.connection(), actor.id);
    runStatement(m_database.connection(),
                 QStringLiteral("INSERT OR IGNORE INTO case_assignments (case_id, cohort_id, assigned_by) "
                                "VALUES (?, ?, ?)"),
                 {caseId, cohortId, actor.id});
    QSqlQuery id = runStatement(m_database.connection(),
                                QStringLiteral("SELECT id FROM case_assignments WHERE case_id = ? AND "
                                               "cohort_id = ?"),
                                {caseId, cohortId});
    id.next();
    const qint64 out = id.value(0).toLongLong();
    tx.commit();
    return out;
}

std::vector<AssignmentRow> CaseLibrary::assignments(const Actor& actor, const std::string& trainee)
{
    QSqlQuery user =
        runStatement(m_database.connection(), QStringLiteral("SELECT id FROM users WHERE name = ?"),
                     {QString::fromStdString(trainee)});
    if (!user.next()) {
        throw DatabaseError("user \"" + trainee + "\" does not exist");
    }
    const qint64 userId = user.value(0).toLongLong();
    const bool readable = actor.role == Role::Administrator || actor.id == userId ||
                          (actor.role == Role::Instructor && teaches(actor.id, userId));
    if (!readable) {
        throw AccessDenied(who(actor) + " may not read the assignments of " + trainee +
                           (actor.role == Role::Instructor
                                ? ": an instructor reads only the students of their cohorts"
                                : ": a student reads only their own records"));
    }
    QSqlQuery query = runStatement(
        m_database.connection(),
        QStringLiteral("SELECT a.id, a.case_id, c.name, coalesce(g.name, ''), b.name, a.assigned_at FROM "
                       "case_assignments a JOIN cases c ON c.id = a.case_id JOIN users b ON b.id = "
                       "a.assigned_by LEFT JOIN cohorts g ON g.id = a.cohort_id WHERE a.user_id = ? OR "
                       "a.cohort_id IN (SELECT cohort_id FROM cohort_members WHERE user_id = ?) ORDER BY "
                       "a.id"),
        {userId, userId});
    std::vector<AssignmentRow> out;
    while (query.next()) {
        out.push_back({query.value(0).toLongLong(), query.value(1).toLongLong(), text(query.value(2)),
                       text(query.value(3)), text(query.value(4)), text(query.value(5))});
    }
    return out;
}

}  // namespace colonosim::db
