#include "db/Cohorts.h"

#include "db/Statement.h"

#include <QVariant>

#include <map>

namespace colonosim::db {

std::vector<CohortRow> readableCohorts(Database& database, const Actor& actor)
{
    QString sql = QStringLiteral("SELECT id, name FROM cohorts");
    QVariantList binds;
    if (actor.role == Role::Instructor) {
        sql += QStringLiteral(" WHERE id IN (SELECT cohort_id FROM cohort_instructors WHERE user_id = ?)");
        binds = {actor.id};
    } else if (actor.role == Role::Student) {
        sql += QStringLiteral(" WHERE id IN (SELECT cohort_id FROM cohort_members WHERE user_id = ?)");
        binds = {actor.id};
    }
    sql += QStringLiteral(" ORDER BY name");
    QSqlDatabase db = database.connection();
    QSqlQuery query = runStatement(db, sql, binds);
    std::vector<CohortRow> out;
    std::map<qint64, size_t> index;
    while (query.next()) {
        index[query.value(0).toLongLong()] = out.size();
        out.push_back({query.value(0).toLongLong(), query.value(1).toString().toStdString(), {}, {}});
    }
    const auto fill = [&](const QString& table, std::vector<std::string> CohortRow::*list) {
        QSqlQuery people = runStatement(
            db, QStringLiteral("SELECT t.cohort_id, u.name FROM %1 t JOIN users u ON u.id = t.user_id "
                               "ORDER BY u.name")
                    .arg(table));
        while (people.next()) {
            if (const auto it = index.find(people.value(0).toLongLong()); it != index.end()) {
                (out[it->second].*list).push_back(people.value(1).toString().toStdString());
            }
        }
    };
    fill(QStringLiteral("cohort_members"), &CohortRow::members);
    fill(QStringLiteral("cohort_instructors"), &CohortRow::instructors);
    return out;
}

}  // namespace colonosim::db
