#include "db/CertificationRules.h"

#include "db/Statement.h"

#include <QVariant>

#include <algorithm>

namespace colonosim::db {

namespace {

/// The columns rowOf() reads, and where they come from.
const QString kFields =
    QStringLiteral("SELECT r.id, r.name, r.version, coalesce(u.name, ''), r.imported_at, r.active");
const QString kFrom =
    QStringLiteral(" FROM certification_rule_sets r LEFT JOIN users u ON u.id = r.imported_by");
const QString kColumns = kFields + kFrom;

RuleSetVersion rowOf(const QSqlQuery& query)
{
    return {query.value(0).toLongLong(),
            query.value(1).toString().toStdString(),
            query.value(2).toInt(),
            query.value(3).toString().toStdString(),
            query.value(4).toString().toStdString(),
            query.value(5).toInt() == 1};
}

int newestVersion(QSqlDatabase db)
{
    QSqlQuery query =
        runStatement(db, QStringLiteral("SELECT coalesce(max(version), 0) FROM certification_rule_sets"));
    query.next();
    return query.value(0).toInt();
}

/// The line of the <certification> element (the file was parsed: it is there).
int rootLine(const std::string& xml)
{
    const auto at = xml.find("<certification");
    return 1 + static_cast<int>(std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

}  // namespace

RuleSetVersion CertificationRules::import(const Actor& actor, const std::string& xml,
                                          const std::string& label)
{
    requireAdministrator(actor, "import certification rule sets");
    const curricula::RuleSetRead read = curricula::parseRuleSet(xml, label);
    if (!read.ok()) {
        throw RuleSetRejected(label + " was not imported: " + std::to_string(read.errors.size()) +
                                  " problem(s) to fix",
                              read.errors);
    }
    QSqlDatabase db = m_database.connection();
    WriteTransaction tx(db, actor.id);
    const int newest = newestVersion(db);
    if (read.value->version <= newest) {
        const std::string error = label + ":" + std::to_string(rootLine(xml)) +
                                  ": <certification> version = " + std::to_string(read.value->version) +
                                  " is already taken or older: a new rule set needs a version of at least " +
                                  std::to_string(newest + 1);
        throw RuleSetRejected(label + " was not imported: 1 problem(s) to fix", {error});
    }
    QSqlQuery insert = runStatement(
        db,
        QStringLiteral(
            "INSERT INTO certification_rule_sets (name, version, xml, imported_by) VALUES (?, ?, ?, ?)"),
        {QString::fromStdString(read.value->name), read.value->version, QString::fromStdString(xml),
         actor.id});
    const qint64 id = insert.lastInsertId().toLongLong();
    QSqlQuery row = runStatement(db, kColumns + QStringLiteral(" WHERE r.id = ?"), {id});
    row.next();
    RuleSetVersion out = rowOf(row);
    tx.commit();
    return out;
}

void CertificationRules::activate(const Actor& actor, int version)
{
    requireAdministrator(actor, "activate certification rule sets");
    QSqlDatabase db = m_database.connection();
    WriteTransaction tx(db, actor.id);
    QSqlQuery exists = runStatement(
        db, QStringLiteral("SELECT active FROM certification_rule_sets WHERE version = ?"), {version});
    if (!exists.next()) {
        std::string stored;
        for (QSqlQuery all = runStatement(
                 db, QStringLiteral("SELECT version FROM certification_rule_sets ORDER BY version"));
             all.next();) {
            stored += (stored.empty() ? "" : ", ") + all.value(0).toString().toStdString();
        }
        throw DatabaseError("certification rule set version " + std::to_string(version) +
                            " is not stored: the stored versions are " + stored);
    }
    if (exists.value(0).toInt() == 1) {
        return;  // already active: nothing changes, nothing to audit
    }
    runStatement(db, QStringLiteral("UPDATE certification_rule_sets SET active = 0 WHERE active = 1"));
    runStatement(db, QStringLiteral("UPDATE certification_rule_sets SET active = 1 WHERE version = ?"),
                 {version});
    tx.commit();
}

std::vector<RuleSetVersion> CertificationRules::versions(const Actor&)
{
    QSqlQuery query = runStatement(m_database.connection(), kColumns + QStringLiteral(" ORDER BY r.version"));
    std::vector<RuleSetVersion> out;
    while (query.next()) {
        out.push_back(rowOf(query));
    }
    return out;
}

ActiveRuleSet CertificationRules::active(const Actor&)
{
    QSqlQuery query = runStatement(m_database.connection(), kFields + QStringLiteral(", r.xml") + kFrom +
                                                                QStringLiteral(" WHERE r.active = 1"));
    if (!query.next()) {
        throw DatabaseError("no certification rule set is active: an administrator activates one");
    }
    const RuleSetVersion stored = rowOf(query);
    const std::string label = stored.name + " version " + std::to_string(stored.version);
    curricula::RuleSetRead read = curricula::parseRuleSet(query.value(6).toString().toStdString(), label);
    if (!read.ok()) {
        throw DatabaseError("the active certification rule set (" + label +
                            ") no longer validates: " + read.errors.front());
    }
    return {stored, std::move(*read.value)};
}

std::string CertificationRules::xml(const Actor&, int version)
{
    QSqlQuery query =
        runStatement(m_database.connection(),
                     QStringLiteral("SELECT xml FROM certification_rule_sets WHERE version = ?"), {version});
    if (!query.next()) {
        throw DatabaseError("certification rule set version " + std::to_string(version) + " is not stored");
    }
    return query.value(0).toString().toStdString();
}

}  // namespace colonosim::db
