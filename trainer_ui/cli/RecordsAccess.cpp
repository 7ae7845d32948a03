#include "trainer_ui/cli/RecordsAccess.h"

#include "curricula/Curriculum.h"
#include "curricula/Progression.h"
#include "db/Password.h"
#include "scoring/Benchmarks.h"
#include "scoring/DomainScores.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QStandardPaths>

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace colonosim::cli {

void ensureQtApplication(bool gui)
{
    if (QCoreApplication::instance()) {
        return;
    }
    static int argc = 1;
    static char name[] = "colonosim";
    static char* argv[] = {name, nullptr};
    QCoreApplication::setApplicationName(QStringLiteral("colonosim"));
    if (gui) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        static QGuiApplication app(argc, argv);
    } else {
        static QCoreApplication app(argc, argv);
    }
}

std::filesystem::path defaultDatabasePath()
{
    ensureQtApplication();
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    if (dir.isEmpty()) {
        throw UsageError("no user data directory is known here; give --db FILE");
    }
    return std::filesystem::path(dir.toStdString()) / "records.sqlite";
}

std::filesystem::path databasePath(const CommandLine& line)
{
    const std::optional<std::string> given = line.value("--db");
    return given ? std::filesystem::path(*given) : defaultDatabasePath();
}

OpenRecords openRecords(const CommandLine& line, std::ostream& notices)
{
    ensureQtApplication();
    const std::filesystem::path path = databasePath(line);
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path());
    }
    OpenRecords out;
    out.database = std::make_unique<db::Database>(path);
    out.records = std::make_unique<db::Records>(*out.database);
    if (out.database->abortedOnOpen() > 0) {
        notices << "records: " << out.database->abortedOnOpen()
                << " interrupted session(s) marked aborted; they do not count\n";
    }
    if (out.records->empty()) {
        const char* chosen = std::getenv("COLONOSIM_ADMIN_PASSWORD");
        const std::string password = chosen && *chosen ? chosen : db::randomPassword();
        out.firstAdministrator = seedFirstStart(*out.records, "admin", password);
        notices << "records: first start of " << path.string() << ": administrator \"admin\" created";
        if (chosen && *chosen) {
            notices << " with the password from COLONOSIM_ADMIN_PASSWORD\n";
        } else {
            notices
                << " with the password " << password
                << "\n  (shown once: keep it, or change it with colonosim user passwd admin --as admin)\n";
        }
    }
    return out;
}

OpenRecords openExistingRecords(const CommandLine& line)
{
    const std::filesystem::path path = databasePath(line);
    if (!std::filesystem::is_regular_file(path)) {
        throw UsageError(
            "records database = " + path.string() +
            ": there is no such file (it must be the database that issued the report; --db FILE)");
    }
    return openRecords(line, std::cerr);
}

db::Actor seedFirstStart(db::Records& records, const std::string& administrator, const std::string& password)
{
    const db::Actor admin = records.bootstrapAdministrator(administrator, password);
    records.storeCurriculum(admin, kCoreCurriculum, curricula::coreCurriculumXml());
    return admin;
}

std::string readSecret(const CommandLine& line, const std::string& fileOption, const char* envVar,
                       const std::string& what)
{
    if (const auto file = line.value(fileOption)) {
        std::ifstream in(*file);
        std::string secret;
        if (!in || !std::getline(in, secret)) {
            throw UsageError(fileOption + " " + *file + ": cannot read the " + what);
        }
        return secret;
    }
    if (const char* value = std::getenv(envVar); value && *value) {
        return value;
    }
    throw UsageError("the " + what + " is needed: set " + envVar + " or give " + fileOption +
                     " FILE (never as an argument)");
}

db::Actor authenticate(db::Records& records, const CommandLine& line, const std::string& name)
{
    if (name.empty()) {
        throw UsageError("--as NAME is required: the user this command acts for");
    }
    const std::string password =
        readSecret(line, "--password-file", "COLONOSIM_PASSWORD", "password of " + name);
    try {
        return records.authenticate(name, password);
    } catch (const db::AuthenticationFailed& error) {
        throw UsageError(error.what());
    }
}

void scoreInto(db::Records& records, const db::Actor& actor, const std::string& task,
               const scoring::MetricValues& values, db::SessionResult& result)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    const curricula::Task* entry = curriculum.value->find(task);
    result.metrics = values;
    result.curriculum = curriculum.value->name;
    bool met = false;
    if (const auto stored = records.latestBenchmarkSet(entry->benchmark)) {
        const auto& [id, version, json] = *stored;
        const scoring::BenchmarkSet set = scoring::BenchmarkSet::fromJson(json);
        result.scores = scoring::scoreSession(values, set);
        met = set.met(values);
        result.scores["benchmark_met"] = met ? 1.0 : 0.0;
        result.benchmarkSetId = id;
    }
    std::vector<curricula::Attempt> attempts;
    for (const db::SessionRow& s : records.sessions(actor, actor.name)) {
        const auto it = s.scores.find("benchmark_met");
        attempts.push_back({s.task, it != s.scores.end() && it->second > 0.5});
    }
    attempts.push_back({task, met});
    for (const auto& [id, state] : curricula::progression(*curriculum.value, attempts)) {
        result.progress[id] = curricula::stateName(state);
    }
}

}  // namespace colonosim::cli
