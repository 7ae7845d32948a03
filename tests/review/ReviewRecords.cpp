#include "tests/review/ReviewRecords.h"

#include "curricula/Curriculum.h"
#include "scoring/Benchmarks.h"
#include "scoring/SessionMetrics.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/cli/SessionStore.h"

#include <random>

namespace colonosim::test {

namespace {

struct Run {
    std::string operatorName;
    double seconds;
};

/// One procedure of `run`, stored and scored for `student`.
qint64 storeRun(db::Records& records, const db::Actor& student, const geometry::ColonAnatomy& anatomy,
                const Run& run, scoring::MetricValues* metrics = nullptr)
{
    procedure::ProcedureSettings settings;
    procedure::ProcedureLoop loop(anatomy, settings);
    const auto driver = procedure::makeOperator(run.operatorName);
    const qint64 session =
        records.beginSession(student, std::nullopt, "navigation-straight", "scripted:" + run.operatorName);
    const auto steps = static_cast<long>(run.seconds / loop.trace().loopStep);
    for (long s = 0; s < steps && !driver->finished(); ++s) {
        loop.step(driver->next(loop));
    }
    scoring::ScoringContext context;
    context.colonLength = loop.colonLength();
    const scoring::MetricValues values = scoring::computeMetrics(loop.recording(), context);
    if (metrics) {
        *metrics = values;
    }
    db::SessionResult result = cli::storedSession(loop, loop.recording());
    cli::scoreInto(records, student, "navigation-straight", values, result);
    records.completeSession(student, session, result);
    return session;
}

}  // namespace

ReviewRecords& ReviewRecords::instance()
{
    static ReviewRecords records;
    return records;
}

ReviewRecords::ReviewRecords()
{
    std::random_device device;
    dir = std::filesystem::temp_directory_path() / ("colonosim-review-" + std::to_string(device()));
    std::filesystem::create_directories(dir);
    database = std::make_unique<db::Database>(dir / "records.sqlite");
    records = std::make_unique<db::Records>(*database);
    admin = records->bootstrapAdministrator("admin", "admin-password");
    records->storeCurriculum(admin, "colonoscopy-core", curricula::coreCurriculumXml());
    records->addUser(admin, "teacher", db::Role::Instructor, kTeacherPassword);
    records->addUser(admin, "ada", db::Role::Student, "ada-password");
    records->addUser(admin, "bob", db::Role::Student, "bob-password");
    records->addCohort(admin, "A");
    records->addMember(admin, "A", "ada");
    records->addMember(admin, "A", "bob");
    records->assignInstructor(admin, "A", "teacher");
    teacher = records->authenticate("teacher", kTeacherPassword);
    ada = records->authenticate("ada", "ada-password");
    bob = records->authenticate("bob", "bob-password");

    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    // The benchmark: expert runs of the teacher (an instructor may run sessions for themselves).
    std::vector<scoring::MetricValues> expertRuns(2);
    storeRun(*records, teacher, anatomy, {"expert", 1.5}, &expertRuns[0]);
    storeRun(*records, teacher, anatomy, {"expert", 2.0}, &expertRuns[1]);
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    const std::string benchmark = curriculum.value->find("navigation-straight")->benchmark;
    scoring::BenchmarkSet set = scoring::deriveBenchmarks(benchmark, 1, 1.0, expertRuns);
    // These expert runs are 1.5-2 s fragments; experts' complete runs reach the
    // cecum, and a set drawn from them demands it: so does this one, or every
    // fragment here would score 100 on a dashboard that a person reads.
    set.metrics["cecal_intubation"] = {1.0, 0.0, 2};
    records->storeBenchmarkSet(admin, benchmark, 1, set.toJson());

    for (const Run& run : {Run{"novice", 1.0}, Run{"expert", 1.0}, Run{"novice", 2.0}, Run{"expert", 2.0}}) {
        adaSessions.push_back(storeRun(*records, ada, anatomy, run));
    }
    for (const Run& run : {Run{"novice", 1.5}, Run{"expert", 1.5}}) {
        bobSessions.push_back(storeRun(*records, bob, anatomy, run));
    }
}

ReviewRecords::~ReviewRecords()
{
    records.reset();
    database.reset();
    std::filesystem::remove_all(dir);
}

}  // namespace colonosim::test
