#include "db/Statement.h"

#include <QSqlError>
#include <QVariant>

namespace colonosim::db {

QSqlQuery runStatement(QSqlDatabase db, const QString& sql, const QVariantList& binds)
{
    QSqlQuery query(db);
    query.setForwardOnly(true);
    if (!query.prepare(sql)) {
        throw DatabaseError(sql.toStdString() + ": " + query.lastError().text().toStdString());
    }
    for (const QVariant& b : binds) {
        query.addBindValue(b);
    }
    if (!query.exec()) {
        throw DatabaseError(query.lastError().text().toStdString() +
                            " (in: " + sql.simplified().toStdString() + ")");
    }
    return query;
}

WriteTransaction::WriteTransaction(QSqlDatabase db, std::optional<qint64> actor) : m_db(db)
{
    runStatement(m_db, QStringLiteral("BEGIN IMMEDIATE"));
    m_open = true;
    runStatement(m_db, QStringLiteral("UPDATE actor_context SET user_id = ? WHERE id = 1"),
                 {actor ? QVariant(*actor) : QVariant()});
}

WriteTransaction::~WriteTransaction()
{
    if (m_open) {
        QSqlQuery(m_db).exec(QStringLiteral("ROLLBACK"));
    }
}

void WriteTransaction::commit()
{
    runStatement(m_db, QStringLiteral("COMMIT"));
    m_open = false;
}

}  // namespace colonosim::db
