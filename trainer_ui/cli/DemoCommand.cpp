/// \file
/// `colonosim demo [--db FILE] [--out DIR] [--max-time S] [--seed N] [--json]` (and `colonosim` with no
/// arguments on a machine with no display): the whole pipeline, headless, on the records database (the
/// default one unless --db):
///   1. generate a case (seed N, no constraints) and store it in the case library;
///   2. run the scripted expert operator on it for at most S simulated seconds;
///   3. score the session into the records as the trainee "demo-student" (created on first use, by the
///      administrator of a fresh database or the one whose password is in COLONOSIM_ADMIN_PASSWORD; its own
///      password is kept next to the database in FILE.demo-student, mode 0600);
///   4. write the trainee's PDF progress report (the signed certification report is the administrator's:
///      colonosim report --format pdf).
/// It prints where the database, the case and the report are.
/// `colonosim demo --tissue ...` is the tissue demonstration of the simulator's foundation.

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseWriter.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "db/Password.h"
#include "scoring/SessionMetrics.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/cli/CaseArgument.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/cli/SessionCoverage.h"
#include "trainer_ui/cli/SessionStore.h"
#include "trainer_ui/reports/TraineeReport.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

namespace colonosim::cli {

int runTissueDemo(std::span<char* const> args);

namespace {

constexpr const char* kDemoStudent = "demo-student";
constexpr const char* kDemoTask = "navigation-straight";

/// The demo trainee, created on first use; its password lives in `credentials`.
db::Actor demoStudent(OpenRecords& open, const std::filesystem::path& credentials)
{
    std::ifstream in(credentials);
    std::string password;
    if (in && std::getline(in, password) && !password.empty()) {
        try {
            return open.records->authenticate(kDemoStudent, password);
        } catch (const db::AuthenticationFailed&) {
            throw UsageError(credentials.string() + " does not hold the password of \"" + kDemoStudent +
                             "\" any more; an administrator can set it with colonosim user passwd " +
                             kDemoStudent + " --as admin, then write it into that file");
        }
    }
    std::optional<db::Actor> admin = open.firstAdministrator;
    if (!admin) {
        const char* adminPassword = std::getenv("COLONOSIM_ADMIN_PASSWORD");
        if (!adminPassword || !*adminPassword) {
            throw UsageError(std::string("the demonstration's trainee \"") + kDemoStudent +
                             "\" has no password file (" + credentials.string() +
                             "): set COLONOSIM_ADMIN_PASSWORD to the password of \"admin\" so the "
                             "demonstration can create it, or give --db a new file");
        }
        try {
            admin = open.records->authenticate("admin", adminPassword);
        } catch (const db::AuthenticationFailed& error) {
            throw UsageError(std::string(error.what()) + " (COLONOSIM_ADMIN_PASSWORD)");
        }
    }
    password = db::randomPassword();
    bool exists = false;
    for (const db::UserRow& u : open.records->listUsers(*admin)) {
        exists = exists || u.name == kDemoStudent;
    }
    if (exists) {
        open.records->setPassword(*admin, kDemoStudent, password);
    } else {
        open.records->addUser(*admin, kDemoStudent, db::Role::Student, password);
    }
    {
        std::ofstream out(credentials, std::ios::trunc);
        out << password << '\n';
        if (!out) {
            throw UsageError(credentials.string() + " cannot be written: " + std::strerror(errno));
        }
    }
    std::filesystem::permissions(credentials,
                                 std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    return open.records->authenticate(kDemoStudent, password);
}

}  // namespace

int runDemo(std::span<char* const> args)
{
    for (size_t k = 0; k < args.size(); ++k) {
        if (std::strcmp(args[k], "--tissue") == 0) {
            std::vector<char*> rest(args.begin(), args.end());
            rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
            return runTissueDemo(std::span<char* const>(rest.data(), rest.size()));
        }
    }
    const CommandLine line(args, {"--json", "--help"}, {"--db", "--out", "--max-time", "--seed"});
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim demo [--db FILE] [--out DIR] [--max-time S] [--seed N] [--json]\n"
               "       colonosim demo --tissue [--duration S] [--integrator NAME] [--json]\n"
               "The whole pipeline, headless: generate a case, run the expert operator on it, score the\n"
               "session into the records as \"demo-student\", write the trainee's PDF report.\n"
               "  --db FILE      the records database (default: records.sqlite in the user's data "
               "directory)\n"
               "  --out DIR      where the case and the report go (default: demo/ beside the database)\n"
               "  --max-time S   simulated seconds of the procedure, 1-900 (default 10)\n"
               "  --seed N       the case generator's seed, 0-1000000 (default 1)\n"
               "  --tissue       the tissue demonstration instead (its own options, see demo --tissue "
               "--help)\n";
        return 0;
    }
    const double maxTime = line.number("--max-time", 10.0, 1.0, 900.0, "s");
    const auto seed = static_cast<std::uint64_t>(std::llround(line.number("--seed", 1.0, 0.0, 1e6, "")));
    const bool json = line.has("--json");
    std::ostream& log = json ? std::cerr : std::cout;
    ensureQtApplication(true);

    OpenRecords open = openRecords(line, log);
    const std::filesystem::path database = std::filesystem::absolute(open.database->path());
    const std::filesystem::path out =
        line.value("--out") ? std::filesystem::path(*line.value("--out")) : database.parent_path() / "demo";
    std::filesystem::create_directories(out);
    const db::Actor student = demoStudent(open, database.string() + ".demo-student");

    // 1. the case
    const cases::Case theCase = cases::CaseGenerator().generate(seed);
    const std::string caseXml = cases::writeCase(theCase);
    const std::filesystem::path caseFile = out / ("case-" + std::to_string(seed) + ".xml");
    reports::writeFileWhole(caseFile, caseXml);
    const qint64 caseId = open.records->storeCase(student, caseFile.filename().string(), caseXml);
    log << "1. case: " << theCase.patient.givenName << " " << theCase.patient.familyName << ", "
        << theCase.patient.age << " years, difficulty " << theCase.difficulty.level << " of 5, "
        << theCase.lesions.size() << " lesion(s): " << caseFile.string() << '\n';

    // 2. the expert operator
    const cases::SceneSpec scene = cases::toScene(theCase);
    const procedure::ProcedureSettings settings = cases::procedureSettings(scene);
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    procedure::ProcedureLoop loop(anatomy, settings);
    const qint64 session = open.records->beginSession(student, caseId, kDemoTask, "scripted:expert");
    const auto driver = procedure::makeOperator("expert");
    const auto started = std::chrono::steady_clock::now();
    const auto steps = static_cast<long>(maxTime / loop.trace().loopStep);
    const std::unique_ptr<SessionCoverage> coverage = tryCoverage(anatomy, loop, log);
    for (long s = 0; s < steps && !driver->finished(); ++s) {
        loop.step(driver->next(loop));
        if (coverage) {
            coverage->observe(loop);
        }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    log << "2. expert operator: " << loop.time() << " s simulated in " << wall << " s\n";

    // 3. scored into the records
    scoring::ScoringContext context;
    context.colonLength = loop.colonLength();
    context.lesionsPresent = static_cast<int>(theCase.lesions.size());
    if (coverage) {
        context.mucosaSeen = coverage->finalFraction();
    }
    const db::SessionResult result = completeStoredSession(*open.records, student, session, kDemoTask, loop,
                                                           recordingSeenBy(loop, coverage.get()), context);
    log << "3. session " << session << " of " << kDemoStudent << " stored with " << result.metrics.size()
        << " metrics, task " << kDemoTask << ", "
        << (result.scores.contains("composite")
                ? "composite score " + std::to_string(result.scores.at("composite"))
                : std::string("no composite score yet: no benchmark set is stored for the task (an "
                              "administrator derives one from expert sessions: colonosim benchmarks derive)"))
        << "\n";

    // 4. the report
    const std::filesystem::path report = out / (std::string(kDemoStudent) + "-report.pdf");
    reports::writeFileWhole(report,
                            reports::progressPdf(*open.database, *open.records, student, kDemoStudent));
    log << "4. report: " << report.string() << "\n\nrecords: " << database.string()
        << "\nreport:  " << report.string() << '\n';
    if (json) {
        nlohmann::json summary = {{"database", database.string()}, {"case", caseFile.string()},
                                  {"report", report.string()},     {"session", session},
                                  {"simulated_s", loop.time()},    {"wall_s", wall},
                                  {"scores", result.scores}};
        std::cout << summary.dump(2) << '\n';
    }
    return 0;
}

}  // namespace colonosim::cli
