#pragma once
/// \file
/// Runs a ProcedureLoop on its own thread, so the loop never waits for the
/// UI or the disk: fixed 1 ms steps paced to real time (times a speed factor
/// for replays), or as fast as it can up to a seek target. Input comes in
/// through the Operator (ManualOperator: a triple buffer from the UI);
/// outputs go out as a Snapshot through a triple buffer, published at most
/// kPublishRate times per wall-clock second (once while paused), which the
/// UI polls.
///
/// The loop is built on the runner's thread (settling the colon takes a
/// moment). When the run ends (the operator finished, the time limit, or
/// requestEnd) the thread stops; after `finished()` the UI thread may read
/// the loop (its trace and recording) to store the session.
///
/// Rates: the physics rate is the loop steps per wall-clock second over the
/// last publishing window (1000 Hz when the loop keeps real time).

#include "simcore/geometry/Segment.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "trainer_ui/app/ProcedureScene.h"
#include "trainer_ui/app/TripleBuffer.h"
#include "trainer_ui/cli/SessionCoverage.h"

#include <Eigen/Core>

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace colonosim::app {

/// What the UI shows of the loop at one moment.
struct Snapshot {
    enum class State { Preparing, Running, Paused, Finished, Failed };
    State state = State::Preparing;
    procedure::ProcedureFrame frame;
    scope::TipPose tip;
    Eigen::Matrix3Xd wall;                            ///< physics node positions, m
    std::vector<render::BleedingMark> bleedingMarks;  ///< at their rest points
    std::vector<Eigen::Vector3d> scopeNodes;          ///< the shaft, m
    std::optional<geometry::Segment> loopSegment;
    double lensSoiling = 0.0;  ///< 0..1
    double physicsRate = 0.0;  ///< loop steps per wall-clock second
    /// Loop steps per wall-clock second that real time (times the speed) asks for; 0 before the loop starts.
    double targetRate = 0.0;
    double speed = 1.0;  ///< simulated seconds per wall-clock second asked
    /// Wall area seen so far, 0..1 (the renderer's coverage); < 0 when it is not measured.
    double mucosaSeen = -1.0;
    std::string failure;  ///< when Failed: what went wrong, as a sentence
};

struct RunnerOptions {
    double maxTime = 900.0;  ///< s simulated; the run ends there
    double speed = 1.0;      ///< simulated seconds per wall-clock second
    bool startPaused = false;
    double seekTo = 0.0;  ///< s: run unpaced up to here, then pause (0: no seek)
    /// Measure the renderer's mucosal coverage of the session (cli::SessionCoverage).
    bool coverage = false;
};

class SimulationRunner {
public:
    static constexpr double kPublishRate = 120.0;  ///< snapshots per wall-clock second, at most

    /// Starts the thread. `driver` is used only on the runner's thread
    /// (except through its own thread-safe handover, e.g. ManualOperator).
    SimulationRunner(std::shared_ptr<const ProcedureScene> scene, std::unique_ptr<procedure::Operator> driver,
                     const RunnerOptions& options);
    /// Stops the thread (at the next step) and joins it.
    ~SimulationRunner();
    SimulationRunner(const SimulationRunner&) = delete;
    SimulationRunner& operator=(const SimulationRunner&) = delete;

    void setPaused(bool paused) { m_paused.store(paused, std::memory_order_release); }
    [[nodiscard]] bool paused() const { return m_paused.load(std::memory_order_acquire); }
    /// 0.25-4 (clamped).
    void setSpeed(double speed);
    /// Ends the run at the next step, as when the operator finishes.
    void requestEnd() { m_endRequested.store(true, std::memory_order_release); }

    /// UI thread: takes the newest snapshot if one came; `snapshot()` shows it.
    bool poll() { return m_snapshots.fetch(); }
    [[nodiscard]] const Snapshot& snapshot() const { return m_snapshots.front(); }

    /// True once the thread has stopped (the run ended or failed).
    [[nodiscard]] bool finished() const { return m_finished.load(std::memory_order_acquire); }
    /// After finished(): the loop (null when it could not be built).
    [[nodiscard]] const procedure::ProcedureLoop* loop() const;
    [[nodiscard]] const ProcedureScene& scene() const { return *m_scene; }
    /// After finished(): the session's coverage, 0..1, every hand-over drawn;
    /// none when it was not measured (RunnerOptions::coverage) or the renderer cannot run here.
    [[nodiscard]] std::optional<double> mucosaSeen();
    /// Once finished: the loop's recording with the renderer's lesion
    /// events merged in (cli::recordingSeenBy); waits for the coverage
    /// thread like mucosaSeen. Throws std::logic_error before.
    [[nodiscard]] procedure::Recording recording();

private:
    void run(std::stop_token stop);
    void publish(Snapshot::State state, double physicsRate);

    std::shared_ptr<const ProcedureScene> m_scene;
    std::unique_ptr<procedure::Operator> m_driver;
    RunnerOptions m_options;
    std::unique_ptr<procedure::ProcedureLoop> m_loop;  ///< owned by the thread until finished
    std::unique_ptr<cli::SessionCoverage> m_coverage;  ///< made on the thread; thread-safe
    TripleBuffer<Snapshot> m_snapshots;
    double m_lensSoiling = 0.0;
    std::string m_failure;
    std::atomic<bool> m_paused{false};
    std::atomic<double> m_speed{1.0};
    std::atomic<bool> m_endRequested{false};
    std::atomic<bool> m_finished{false};
    std::jthread m_thread;  ///< last: starts after every member above exists
};

}  // namespace colonosim::app
