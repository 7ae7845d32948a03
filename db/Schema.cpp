#include "db/Schema.h"

#include "curricula/Certification.h"

#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>

#include <vector>

namespace colonosim::db {

namespace {

// Each migration is a list of statements (the QSQLITE driver runs one per exec).
const std::vector<std::vector<const char*>>& migrations()
{
    static const std::vector<std::vector<const char*>> all = {
        // 1: the records
        {
            R"(CREATE TABLE users (
                 id INTEGER PRIMARY KEY,
                 name TEXT NOT NULL UNIQUE CHECK (length(name) BETWEEN 1 AND 64),
                 role TEXT NOT NULL CHECK (role IN ('student', 'instructor', 'administrator')),
                 password_hash TEXT NOT NULL,
                 created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')))
            )",
            R"(CREATE TABLE cohorts (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE))",
            R"(CREATE TABLE cohort_members (
                 cohort_id INTEGER NOT NULL REFERENCES cohorts(id) ON DELETE CASCADE,
                 user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
                 PRIMARY KEY (cohort_id, user_id))
            )",
            R"(CREATE TABLE cohort_instructors (
                 cohort_id INTEGER NOT NULL REFERENCES cohorts(id) ON DELETE CASCADE,
                 user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,
                 PRIMARY KEY (cohort_id, user_id))
            )",
            R"(CREATE TABLE cases (
                 id INTEGER PRIMARY KEY,
                 name TEXT NOT NULL,
                 xml TEXT NOT NULL,
                 sha256 TEXT NOT NULL UNIQUE)
            )",
            R"(CREATE TABLE curricula (
                 id INTEGER PRIMARY KEY,
                 name TEXT NOT NULL UNIQUE,
                 xml TEXT NOT NULL,
                 created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')))
            )",
            R"(CREATE TABLE sessions (
                 id INTEGER PRIMARY KEY,
                 user_id INTEGER NOT NULL REFERENCES users(id),
                 case_id INTEGER REFERENCES cases(id),
                 task TEXT NOT NULL DEFAULT '',
                 device TEXT NOT NULL,
                 owner TEXT NOT NULL,
                 status TEXT NOT NULL CHECK (status IN ('running', 'completed', 'aborted')),
                 started_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 finished_at TEXT,
                 duration_s REAL,
                 trace BLOB,
                 recording BLOB)
            )",
            R"(CREATE TABLE events (
                 session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
                 seq INTEGER NOT NULL,
                 time_s REAL NOT NULL,
                 kind TEXT NOT NULL,
                 detail TEXT NOT NULL DEFAULT '',
                 PRIMARY KEY (session_id, seq))
            )",
            R"(CREATE TABLE metrics (
                 session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
                 name TEXT NOT NULL,
                 value REAL NOT NULL,
                 PRIMARY KEY (session_id, name))
            )",
            R"(CREATE TABLE scores (
                 id INTEGER PRIMARY KEY,
                 session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
                 name TEXT NOT NULL,
                 value REAL NOT NULL,
                 UNIQUE (session_id, name))
            )",
            R"(CREATE TABLE progress (
                 id INTEGER PRIMARY KEY,
                 user_id INTEGER NOT NULL REFERENCES users(id),
                 curriculum TEXT NOT NULL,
                 task TEXT NOT NULL,
                 state TEXT NOT NULL CHECK (state IN ('locked', 'unlocked', 'proficient', 'unavailable')),
                 updated_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 UNIQUE (user_id, curriculum, task))
            )",
            R"(CREATE TABLE certificates (
                 id INTEGER PRIMARY KEY,
                 user_id INTEGER NOT NULL REFERENCES users(id),
                 issued_by INTEGER NOT NULL REFERENCES users(id),
                 issued_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 content_sha256 TEXT NOT NULL,
                 signature TEXT NOT NULL,
                 public_key TEXT NOT NULL)
            )",
            // Who acts: the data-access layer sets the single row inside each
            // write transaction, so the audit triggers can name the actor.
            R"(CREATE TABLE actor_context (id INTEGER PRIMARY KEY CHECK (id = 1), user_id INTEGER))",
            R"(INSERT INTO actor_context (id, user_id) VALUES (1, NULL))",
            R"(CREATE TABLE audit (
                 id INTEGER PRIMARY KEY,
                 at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 actor_id INTEGER,
                 table_name TEXT NOT NULL,
                 row_id INTEGER NOT NULL,
                 action TEXT NOT NULL CHECK (action IN ('insert', 'update', 'delete')),
                 detail TEXT NOT NULL DEFAULT '')
            )",
            R"(CREATE TRIGGER audit_no_update BEFORE UPDATE ON audit
               BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END)",
            R"(CREATE TRIGGER audit_no_delete BEFORE DELETE ON audit
               BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END)",
            R"(CREATE TRIGGER users_audit_insert AFTER INSERT ON users BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'users', NEW.id, 'insert',
                         NEW.name || ' ' || NEW.role); END)",
            R"(CREATE TRIGGER users_audit_update AFTER UPDATE ON users BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'users', NEW.id, 'update',
                         NEW.name || ' ' || NEW.role ||
                         CASE WHEN NEW.password_hash <> OLD.password_hash THEN ' password changed' ELSE '' END);
               END)",
            R"(CREATE TRIGGER users_audit_delete AFTER DELETE ON users BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'users', OLD.id, 'delete', OLD.name);
               END)",
            R"(CREATE TRIGGER scores_audit_insert AFTER INSERT ON scores BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'scores', NEW.id, 'insert',
                         'session ' || NEW.session_id || ' ' || NEW.name || '=' || NEW.value); END)",
            R"(CREATE TRIGGER scores_audit_update AFTER UPDATE ON scores BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'scores', NEW.id, 'update',
                         'session ' || NEW.session_id || ' ' || NEW.name || ' ' || OLD.value || '->' || NEW.value);
               END)",
            R"(CREATE TRIGGER scores_audit_delete AFTER DELETE ON scores BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'scores', OLD.id, 'delete',
                         'session ' || OLD.session_id || ' ' || OLD.name); END)",
            R"(CREATE TRIGGER progress_audit_insert AFTER INSERT ON progress BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'progress', NEW.id, 'insert',
                         NEW.task || ' ' || NEW.state); END)",
            R"(CREATE TRIGGER progress_audit_update AFTER UPDATE ON progress BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'progress', NEW.id, 'update',
                         NEW.task || ' ' || OLD.state || '->' || NEW.state); END)",
            R"(CREATE TRIGGER certificates_audit_insert AFTER INSERT ON certificates BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'certificates', NEW.id, 'insert',
                         'user ' || NEW.user_id || ' sha256 ' || NEW.content_sha256); END)",
            R"(CREATE TRIGGER certificates_audit_update AFTER UPDATE ON certificates BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'certificates', NEW.id, 'update',
                         'user ' || NEW.user_id); END)",
            R"(CREATE TRIGGER certificates_audit_delete AFTER DELETE ON certificates BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'certificates', OLD.id, 'delete',
                         'user ' || OLD.user_id); END)",
        },
        // 2: versioned benchmark sets
        {
            R"(CREATE TABLE benchmark_sets (
                 id INTEGER PRIMARY KEY,
                 name TEXT NOT NULL,
                 version INTEGER NOT NULL CHECK (version >= 1),
                 json TEXT NOT NULL,
                 created_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 UNIQUE (name, version))
            )",
            R"(ALTER TABLE scores ADD COLUMN benchmark_set_id INTEGER REFERENCES benchmark_sets(id))",
        },
        // 3: dashboard indexes
        {
            R"(CREATE INDEX sessions_by_user ON sessions (user_id, status, id))",
            R"(CREATE INDEX scores_by_session ON scores (session_id))",
            R"(CREATE INDEX audit_by_table ON audit (table_name, row_id))",
        },
        // 4: a case assigned to a trainee or to a whole cohort
        {
            R"(CREATE TABLE case_assignments (
                 id INTEGER PRIMARY KEY,
                 case_id INTEGER NOT NULL REFERENCES cases(id) ON DELETE CASCADE,
                 user_id INTEGER REFERENCES users(id) ON DELETE CASCADE,
                 cohort_id INTEGER REFERENCES cohorts(id) ON DELETE CASCADE,
                 assigned_by INTEGER NOT NULL REFERENCES users(id),
                 assigned_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 CHECK ((user_id IS NULL) <> (cohort_id IS NULL)))
            )",
            R"(CREATE UNIQUE INDEX case_assignments_to_user ON case_assignments (case_id, user_id)
                 WHERE user_id IS NOT NULL)",
            R"(CREATE UNIQUE INDEX case_assignments_to_cohort ON case_assignments (case_id, cohort_id)
                 WHERE cohort_id IS NOT NULL)",
            R"(CREATE TRIGGER case_assignments_audit_insert AFTER INSERT ON case_assignments BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'case_assignments', NEW.id,
                         'insert', 'case ' || NEW.case_id ||
                         CASE WHEN NEW.user_id IS NULL THEN ' to cohort ' || NEW.cohort_id
                              ELSE ' to user ' || NEW.user_id END); END)",
        },
        // 5: certification rule sets of record, versioned, one active
        {
            R"(CREATE TABLE certification_rule_sets (
                 id INTEGER PRIMARY KEY,
                 name TEXT NOT NULL CHECK (length(name) BETWEEN 1 AND 200),
                 version INTEGER NOT NULL UNIQUE CHECK (version >= 1),
                 xml TEXT NOT NULL,
                 imported_by INTEGER REFERENCES users(id),
                 imported_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
                 active INTEGER NOT NULL DEFAULT 0 CHECK (active IN (0, 1)))
            )",
            R"(CREATE UNIQUE INDEX certification_rule_sets_one_active ON certification_rule_sets (active)
                 WHERE active = 1)",
            R"(CREATE TRIGGER certification_rule_sets_of_record BEFORE UPDATE OF name, version, xml, imported_by,
                 imported_at ON certification_rule_sets BEGIN
                 SELECT RAISE(ABORT, 'a stored certification rule set is of record: import a new version'); END)",
            R"(CREATE TRIGGER certification_rule_sets_kept BEFORE DELETE ON certification_rule_sets BEGIN
                 SELECT RAISE(ABORT, 'a stored certification rule set is of record: it is never deleted'); END)",
            R"(CREATE TRIGGER certification_rule_sets_audit_insert AFTER INSERT ON certification_rule_sets BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'certification_rule_sets', NEW.id,
                         'insert', 'imported ' || NEW.name || ' version ' || NEW.version ||
                         CASE WHEN NEW.active = 1 THEN ' (active)' ELSE '' END); END)",
            R"(CREATE TRIGGER certification_rule_sets_audit_activate AFTER UPDATE OF active
                 ON certification_rule_sets WHEN NEW.active = 1 AND OLD.active = 0 BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'certification_rule_sets', NEW.id,
                         'update', 'activated ' || NEW.name || ' version ' || NEW.version); END)",
        },
        // 6: a deleted progress row is audited too (scores and certificates were)
        {
            R"(CREATE TRIGGER progress_audit_delete AFTER DELETE ON progress BEGIN
                 INSERT INTO audit (actor_id, table_name, row_id, action, detail)
                 VALUES ((SELECT user_id FROM actor_context WHERE id = 1), 'progress', OLD.id, 'delete',
                         OLD.task || ' ' || OLD.state); END)",
        },
    };
    return all;
}

/// Rows a migration stores besides its statements (bound values, not SQL text).
void seed(QSqlQuery& query, int migration)
{
    if (migration != 5) {
        return;
    }
    // The shipped core rule set becomes version 1 of record, and active.
    const curricula::RuleSetRead core =
        curricula::parseRuleSet(curricula::coreRuleSetXml(), "certification-rules.xml");
    if (!core.ok()) {
        throw DatabaseError("the shipped certification rule set does not parse: " + core.errors.front());
    }
    query.prepare(QStringLiteral("INSERT INTO certification_rule_sets (name, version, xml, imported_by, "
                                 "active) VALUES (?, 1, ?, NULL, 1)"));
    query.addBindValue(QString::fromStdString(core.value->name));
    query.addBindValue(QString::fromStdString(curricula::coreRuleSetXml()));
    if (!query.exec()) {
        throw DatabaseError("cannot store the shipped certification rule set: " +
                            query.lastError().text().toStdString());
    }
}

}  // namespace

int latestSchemaVersion()
{
    return static_cast<int>(migrations().size());
}

int schemaVersion(QSqlDatabase& db)
{
    QSqlQuery query(db);
    if (!query.exec("PRAGMA user_version") || !query.next()) {
        throw DatabaseError("cannot read the schema version: " + query.lastError().text().toStdString());
    }
    return query.value(0).toInt();
}

void migrate(QSqlDatabase& db, int target)
{
    const int latest = latestSchemaVersion();
    if (target < 0) {
        target = latest;
    }
    if (target > latest) {
        throw DatabaseError("schema version " + std::to_string(target) + " is out of range 0-" +
                            std::to_string(latest));
    }
    int version = schemaVersion(db);
    if (version > latest) {
        throw DatabaseError("the database has schema version " + std::to_string(version) +
                            ", newer than this build's " + std::to_string(latest) + " (allowed 0-" +
                            std::to_string(latest) + ")");
    }
    while (version < target) {
        if (!db.transaction()) {
            throw DatabaseError("cannot begin migration " + std::to_string(version + 1) + ": " +
                                db.lastError().text().toStdString());
        }
        QSqlQuery query(db);
        for (const char* statement : migrations()[static_cast<size_t>(version)]) {
            if (!query.exec(QString::fromUtf8(statement))) {
                const std::string error = query.lastError().text().toStdString();
                db.rollback();
                throw DatabaseError("migration " + std::to_string(version + 1) + " failed: " + error +
                                    "\n  in: " + statement);
            }
        }
        try {
            seed(query, version + 1);
        } catch (const DatabaseError&) {
            db.rollback();
            throw;
        }
        if (!query.exec(QStringLiteral("PRAGMA user_version = %1").arg(version + 1)) || !db.commit()) {
            const std::string error = db.lastError().text().toStdString();
            db.rollback();
            throw DatabaseError("cannot finish migration " + std::to_string(version + 1) + ": " + error);
        }
        ++version;
    }
}

}  // namespace colonosim::db
