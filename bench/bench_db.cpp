// The records' speed targets (issue: records):
//   BM_StoreSession     store one 20-minute session: the input trace at 1 kHz
//                       (1.2 million samples, delta coding + zstd) and the
//                       recording at 100 Hz (120,000 samples), 300 events, the
//                       metrics and scores, from insertion as running to the
//                       completing transaction. Target <= 1 s. The counter
//                       db_bytes_per_session is the file's growth per session
//                       (target <= 5 MB).
//   BM_DashboardQuery   one trainee's learning curves (three metrics) across
//                       10,000 stored sessions. Target <= 100 ms.
// The session content is synthetic but shaped like a procedure: smooth
// insertion with hand tremor, slow dial and rotation changes, occasional
// button presses (compressibility close to a real trace).

#include "db/Database.h"
#include "db/RecordingCodec.h"
#include "db/Records.h"
#include "db/StoredTrace.h"
#include "simcore/procedure/InputTrace.h"
#include "simcore/procedure/Recorder.h"

#include <QCoreApplication>
#include <QSqlQuery>

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace colonosim;

constexpr double kSessionTime = 1200.0;  ///< s, 20 minutes

/// Shaped like the scripted operators' input (Operator.h): insertion at a
/// constant speed accumulated step by step (2 s in at 3 cm/s, 0.5 s back at
/// 1 cm/s), dials following a steering target that moves every 0.2 s with a
/// 5 /s gain, shaft rotation following a target that moves every 3 s, a lens
/// wash press of 0.3 s every minute.
procedure::InputTrace syntheticTrace()
{
    procedure::InputTrace trace;
    const auto n = static_cast<size_t>(kSessionTime / trace.loopStep);
    const double dt = trace.loopStep;
    trace.samples.resize(n);
    std::uint64_t lcg = 12345;
    auto uniform = [&lcg] {
        lcg = lcg * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(lcg >> 11) / 9007199254740992.0 - 0.5;  // -0.5 to 0.5
    };
    double insertion = 0.0, rotation = 0.0, up = 0.0, left = 0.0;
    double rotationTarget = 0.0, upTarget = 0.0, leftTarget = 0.0;
    for (size_t k = 0; k < n; ++k) {
        if (k % 200 == 0) {
            upTarget = uniform();
            leftTarget = uniform();
        }
        if (k % 3000 == 0) {
            rotationTarget = 0.6 * uniform();
        }
        insertion += (k % 2500 < 2000 ? 0.03 : -0.01) * dt;
        rotation += 2.0 * (rotationTarget - rotation) * dt;
        up += 5.0 * (upTarget - up) * dt;
        left += 5.0 * (leftTarget - left) * dt;
        auto& s = trace.samples[k];
        s.insertion = insertion;
        s.rotation = rotation;
        s.dialUpDown = up;
        s.dialLeftRight = left;
        s.buttons = k % 60000 < 300 ? procedure::kWater : 0;
        s = procedure::quantizeInput(s);  // as the procedure loop records it
    }
    return trace;
}

procedure::Recording syntheticRecording()
{
    procedure::Recording r;
    const auto n = static_cast<size_t>(kSessionTime / 0.01);
    r.samples.resize(n);
    for (size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * 0.01;
        auto& s = r.samples[k];
        s.time = t;
        s.insertion = 0.8 * (1.0 - std::cos(t / kSessionTime * M_PI));
        s.tip = Eigen::Vector3d(0.1 * std::sin(t / 30), 0.05 * std::cos(t / 20), s.insertion * 0.4);
        s.segment = static_cast<geometry::Segment>((k / 20000) % 6);
        s.handleForce = 4.0 + 3.0 * std::sin(t / 2.0);
        s.handleTorque = 0.05 * std::sin(t / 5.0);
        s.maxWallForce = 1.0 + std::abs(std::sin(t));
        s.mesenteryStrain = 0.02 * std::abs(std::sin(t / 11));
        s.discomfort = 2.0 + 1.5 * std::sin(t / 40);
        s.loop = (k / 3000) % 5 == 0 ? procedure::LoopKind::N : procedure::LoopKind::None;
        s = procedure::quantizeSample(s);  // as the recorder records it
    }
    for (int e = 0; e < 300; ++e) {
        r.events.push_back({4.0 * e, procedure::EventKind::LoopFormed, "N"});
    }
    return r;
}

QByteArray bytes(const std::vector<char>& v)
{
    return QByteArray(v.data(), static_cast<qsizetype>(v.size()));
}

std::filesystem::path freshFile(const char* name)
{
    const auto path =
        std::filesystem::temp_directory_path() / (std::string(name) + std::to_string(::getpid()));
    for (const char* suffix : {"", "-wal", "-shm"}) {
        std::filesystem::remove(path.string() + suffix);
    }
    return path;
}

void BM_StoreSession(benchmark::State& state)
{
    const auto path = freshFile("colonosim-bench-store-");
    db::Database database(path);
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("admin", "bench-password");
    const procedure::InputTrace trace = syntheticTrace();
    const procedure::Recording recording = syntheticRecording();
    std::map<std::string, double> metrics;
    for (int m = 0; m < 30; ++m) {
        metrics["metric_" + std::to_string(m)] = m * 1.5;
    }
    const auto sizeOf = [&] {
        QSqlQuery(database.connection()).exec(QStringLiteral("PRAGMA wal_checkpoint(TRUNCATE)"));
        return std::filesystem::file_size(path);
    };
    const auto before = sizeOf();
    for (auto _ : state) {
        db::SessionResult result;
        const qint64 session = records.beginSession(admin, std::nullopt, "navigation-straight", "bench");
        result.trace = bytes(db::encodeStoredTrace(trace));
        result.recording = bytes(db::encodeRecording(recording));
        result.duration = kSessionTime;
        for (const auto& e : recording.events) {
            result.events.push_back({e.time, "LoopFormed", e.detail});
        }
        result.metrics = metrics;
        result.scores = {{"composite", 71.0}, {"benchmark_met", 1.0}};
        records.completeSession(admin, session, result);
    }
    state.counters["db_bytes_per_session"] =
        static_cast<double>(sizeOf() - before) / static_cast<double>(state.iterations());
    state.counters["trace_bytes"] = static_cast<double>(db::encodeStoredTrace(trace).size());
    state.counters["recording_bytes"] = static_cast<double>(db::encodeRecording(recording).size());
    std::filesystem::remove(path);
}
BENCHMARK(BM_StoreSession)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_DashboardQuery(benchmark::State& state)
{
    const auto path = freshFile("colonosim-bench-dashboard-");
    db::Database database(path);
    db::Records records(database);
    const db::Actor admin = records.bootstrapAdministrator("admin", "bench-password");
    records.addUser(admin, "trainee", db::Role::Student, "bench-password");
    records.addUser(admin, "other", db::Role::Student, "bench-password");
    {
        // 10,000 sessions of the trainee (and 10,000 of another), 30 metrics each, in one transaction.
        QSqlDatabase c = database.connection();
        QSqlQuery q(c);
        q.exec(QStringLiteral("BEGIN"));
        QSqlQuery session(c), metric(c);
        session.prepare(
            QStringLiteral("INSERT INTO sessions (user_id, task, device, owner, status, duration_s) "
                           "VALUES (?, 'navigation-straight', 'bench', 'bench:0', 'completed', 600)"));
        metric.prepare(QStringLiteral("INSERT INTO metrics (session_id, name, value) VALUES (?, ?, ?)"));
        for (int n = 0; n < 20000; ++n) {
            session.addBindValue(n % 2 == 0 ? 2 : 3);
            session.exec();
            const qint64 id = session.lastInsertId().toLongLong();
            for (int m = 0; m < 30; ++m) {
                metric.addBindValue(id);
                metric.addBindValue(QStringLiteral("metric_%1").arg(m));
                metric.addBindValue(n * 0.01 + m);
                metric.exec();
            }
        }
        q.exec(QStringLiteral("COMMIT"));
    }
    const db::Actor trainee = records.authenticate("trainee", "bench-password");
    size_t points = 0;
    for (auto _ : state) {
        points = 0;
        for (const char* m : {"metric_1", "metric_7", "metric_20"}) {
            points += records.learningCurve(trainee, "trainee", m).size();
        }
        benchmark::DoNotOptimize(points);
    }
    state.counters["points"] = static_cast<double>(points);
    std::filesystem::remove(path);
}
BENCHMARK(BM_DashboardQuery)->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
