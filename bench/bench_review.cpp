// The review screens' speed (issue: trainer):
//   BM_InstructorDashboardOpen  an instructor opens their home screen when one
//                               trainee of their cohort has 10,000 completed
//                               sessions (30+ metrics each) and another has
//                               100: every page is built (trainee tree with
//                               progress, learning curve and CUSUM charts,
//                               session table, comparison lists, case
//                               library) and painted once.
//   BM_CohortExport/FORMAT      the administrator's export of a cohort of 10
//                               trainees with 50 sessions each (csv, xapi,
//                               pdf: signed, one per trainee); the counter
//                               ms_per_trainee is the figure to quote.
// The stored values are synthetic (the scoring code's metric names, values
// that vary per session); the timings are those of the queries, the charts
// and the report writers, not of the simulation.
// Run under a display (xvfb-run -a build/bench/bench_review) or headless
// (QT_QPA_PLATFORM=offscreen, set when no DISPLAY is given).

#include "db/Database.h"
#include "db/Records.h"
#include "scoring/MetricDefinitions.h"
#include "trainer_ui/reports/CohortExport.h"
#include "trainer_ui/review/InstructorHome.h"

#include <QApplication>
#include <QSqlQuery>
#include <QTabWidget>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace colonosim;

std::filesystem::path freshDir(const char* name)
{
    const auto path =
        std::filesystem::temp_directory_path() / (std::string(name) + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    return path;
}

/// `count` completed sessions of `userId`, with every declared metric and the
/// scores the scoring code writes, in one transaction.
void storeSessions(db::Database& database, qint64 userId, int count)
{
    QSqlDatabase c = database.connection();
    QSqlQuery(c).exec(QStringLiteral("BEGIN"));
    QSqlQuery session(c), metric(c), score(c);
    session.prepare(QStringLiteral("INSERT INTO sessions (user_id, task, device, owner, status, duration_s) "
                                   "VALUES (?, 'navigation-straight', 'bench', 'bench:0', 'completed', ?)"));
    metric.prepare(QStringLiteral("INSERT INTO metrics (session_id, name, value) VALUES (?, ?, ?)"));
    score.prepare(QStringLiteral("INSERT INTO scores (session_id, name, value) VALUES (?, ?, ?)"));
    for (int n = 0; n < count; ++n) {
        const double learnt = 1.0 - std::exp(-n / 50.0);
        session.addBindValue(userId);
        session.addBindValue(600.0 - 300.0 * learnt);
        session.exec();
        const qint64 id = session.lastInsertId().toLongLong();
        int m = 0;
        for (const scoring::MetricDefinition& d : scoring::metricDefinitions()) {
            metric.addBindValue(id);
            metric.addBindValue(QString::fromUtf8(d.name.data(), static_cast<qsizetype>(d.name.size())));
            metric.addBindValue(d.name == "cecal_intubation" ? ((n * 7919) % 10 < 9 * learnt ? 1.0 : 0.0)
                                                             : 1.0 + 0.1 * m + learnt * std::sin(n + m));
            metric.exec();
            ++m;
        }
        for (const auto& [name, value] : {std::pair{"composite", 50.0 + 40.0 * learnt},
                                          std::pair{"benchmark_met", learnt > 0.8 ? 1.0 : 0.0}}) {
            score.addBindValue(id);
            score.addBindValue(QString::fromLatin1(name));
            score.addBindValue(value);
            score.exec();
        }
    }
    QSqlQuery(c).exec(QStringLiteral("COMMIT"));
}

void BM_InstructorDashboardOpen(benchmark::State& state)
{
    const auto dir = freshDir("colonosim-bench-review-");
    {
        db::Database database(dir / "records.sqlite");
        db::Records records(database);
        const db::Actor admin = records.bootstrapAdministrator("admin", "bench-password");
        records.addUser(admin, "teacher", db::Role::Instructor, "bench-password");
        const qint64 busy = records.addUser(admin, "busy-trainee", db::Role::Student, "bench-password");
        const qint64 other = records.addUser(admin, "other-trainee", db::Role::Student, "bench-password");
        records.addCohort(admin, "A");
        records.addMember(admin, "A", "busy-trainee");
        records.addMember(admin, "A", "other-trainee");
        records.assignInstructor(admin, "A", "teacher");
        storeSessions(database, busy, 10000);
        storeSessions(database, other, 100);
        const db::Actor teacher = records.authenticate("teacher", "bench-password");
        app::AppContext context{database, records, teacher, dir};
        const bool everyTab = state.range(0) != 0;
        std::vector<double> tabSeconds;
        for (auto _ : state) {
            app::InstructorHome home(context);
            home.resize(1400, 900);
            home.show();
            QApplication::processEvents();
            if (everyTab) {
                auto* tabs = home.findChild<QTabWidget*>(QStringLiteral("instructorTabs"));
                tabSeconds.resize(static_cast<size_t>(tabs->count()));
                for (int k = 1; k < tabs->count(); ++k) {
                    const auto start = std::chrono::steady_clock::now();
                    tabs->setCurrentIndex(k);
                    QApplication::processEvents();
                    tabSeconds[static_cast<size_t>(k)] +=
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                }
            }
            benchmark::DoNotOptimize(home.isVisible());
        }
        for (size_t k = 1; k < tabSeconds.size(); ++k) {
            state.counters["ms_tab" + std::to_string(k)] =
                1e3 * tabSeconds[k] / static_cast<double>(state.iterations());
        }
        state.SetLabel(everyTab ? "every_tab (tab1 curves, tab2 sessions, tab3 cases, tab4 comparison)"
                                : "first_tab");
    }
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_InstructorDashboardOpen)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_CohortExport(benchmark::State& state)
{
    const auto format = static_cast<reports::ReportFormat>(state.range(0));
    constexpr int kTrainees = 10;
    const auto dir = freshDir("colonosim-bench-export-");
    {
        db::Database database(dir / "records.sqlite");
        db::Records records(database);
        const db::Actor admin = records.bootstrapAdministrator("admin", "bench-password");
        std::vector<std::string> trainees;
        records.addCohort(admin, "A");
        for (int t = 0; t < kTrainees; ++t) {
            trainees.push_back("trainee-" + std::to_string(t));
            storeSessions(database,
                          records.addUser(admin, trainees.back(), db::Role::Student, "bench-password"), 50);
            records.addMember(admin, "A", trainees.back());
        }
        int run = 0;
        double seconds = 0.0;
        for (auto _ : state) {
            const auto out = dir / ("export-" + std::to_string(run++));
            const auto start = std::chrono::steady_clock::now();
            reports::exportCohort(format, database, records, admin, trainees, out, std::stop_token{});
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        state.counters["ms_per_trainee"] =
            1e3 * seconds / (kTrainees * static_cast<double>(state.iterations()));
        state.SetLabel(reports::formatName(format));
    }
    std::filesystem::remove_all(dir);
}
BENCHMARK(BM_CohortExport)
    ->Arg(static_cast<int>(reports::ReportFormat::Csv))
    ->Arg(static_cast<int>(reports::ReportFormat::Xapi))
    ->Arg(static_cast<int>(reports::ReportFormat::Pdf))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
