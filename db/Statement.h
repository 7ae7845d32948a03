#pragma once
/// \file
/// What the data-access classes share inside db/: running one prepared
/// statement, and the write transaction that names the actor for the audit
/// triggers. Not for use above db/.

#include "db/Schema.h"

#include <QSqlDatabase>
#include <QSqlQuery>
#include <QString>
#include <QVariantList>

#include <optional>
#include <string>

namespace colonosim::db {

/// Prepares, binds in order and runs; throws DatabaseError with the statement.
QSqlQuery runStatement(QSqlDatabase db, const QString& sql, const QVariantList& binds = {});

/// BEGIN IMMEDIATE (takes the write lock at once, so WAL readers never
/// deadlock an upgrade), names the actor for the audit triggers; rolls back
/// unless committed.
class WriteTransaction {
public:
    WriteTransaction(QSqlDatabase db, std::optional<qint64> actor);
    ~WriteTransaction();
    WriteTransaction(const WriteTransaction&) = delete;
    WriteTransaction& operator=(const WriteTransaction&) = delete;
    void commit();

private:
    QSqlDatabase m_db;
    bool m_open = false;
};

}  // namespace colonosim::db
