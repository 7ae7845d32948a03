#pragma once
/// \file
/// The renderer's mucosal coverage of a running session, for scoring (%
/// mucosa visualised) and the heads-up display: a render::CoverageTracker
/// on an offscreen (OSMesa) context of its own thread. The loop's thread
/// only hands over the wall's node positions and the tip pose every
/// coverageInterval of simulated time (10 Hz by default; a copy of about
/// 46 kB), so the 1 kHz loop never waits for a draw (about 1.4 ms each).
/// Every hand-over is drawn, in order: the result depends on the simulated
/// session only, and a replayed session covers the same wall.
///
/// It also watches the case's lesions through the same ID buffer, so a fold
/// in front of a lesion hides it (the loop's own "lesion in view" does not
/// test occlusion): LesionOnScreen / LesionOffScreen events at the update
/// times, for the recording that scoring reads (detection, time to
/// detection).

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/render/FisheyeLens.h"

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace colonosim::cli {

class SessionCoverage {
public:
    /// Starts the coverage thread and waits until its context and tracker
    /// are made; throws render::RenderError (or std::runtime_error) when they
    /// cannot be. `lesionTriangles`: each lesion's triangles of the
    /// anatomy's physicsMesh (lesionTrianglesOf), in the case's order.
    explicit SessionCoverage(const geometry::ColonAnatomy& anatomy,
                             std::vector<std::vector<int>> lesionTriangles = {});
    ~SessionCoverage();
    SessionCoverage(const SessionCoverage&) = delete;
    SessionCoverage& operator=(const SessionCoverage&) = delete;

    /// Loop thread, after each step: hands the wall over when coverageInterval has passed.
    void observe(const procedure::ProcedureLoop& loop);
    /// The coverage of everything handed over, once drawn: seen wall area over
    /// the whole wall's, 0-1. Waits for the coverage thread to catch up.
    [[nodiscard]] double finalFraction();
    /// Like finalFraction, by segment (geometry::Segment's order): seen
    /// wall area over the segment's, 0-1 (0 for a segment with no wall).
    [[nodiscard]] std::array<double, geometry::kNumSegments> finalBySegment();
    /// The renderer's lesion events (LesionOnScreen / LesionOffScreen) of
    /// everything handed over, in time order; waits like finalFraction.
    /// Merged into the session's recording before it is scored and stored.
    [[nodiscard]] std::vector<procedure::RecordedEvent> lesionEvents();
    /// The latest coverage drawn so far, 0-1 (never waits; for a display).
    [[nodiscard]] double latestFraction() const { return m_latest.load(std::memory_order_relaxed); }
    /// Wall-clock seconds the coverage thread spent drawing, and the draws.
    [[nodiscard]] double drawSeconds() const;
    [[nodiscard]] int draws() const;

    /// Hand-overs waiting at most (about 12 MB); observe() waits beyond.
    static constexpr size_t kMaxQueued = 256;

private:
    struct Job {
        double time = 0.0;  ///< s simulated
        Eigen::Matrix3Xd positions;
        render::CameraPose pose;
    };
    void work(const geometry::ColonAnatomy& anatomy, std::vector<std::vector<int>> lesionTriangles);
    /// Waits until every hand-over is drawn; returns holding m_mutex.
    std::unique_lock<std::mutex> drained();

    double m_interval = 0.1;  ///< s simulated between hand-overs (RenderParameters::coverageInterval)
    double m_next = 0.0;      ///< s simulated: the next hand-over
    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<Job> m_jobs;   ///< under m_mutex
    bool m_ready = false;     ///< under m_mutex: the worker made its tracker (or failed)
    bool m_stop = false;      ///< under m_mutex
    bool m_busy = false;      ///< under m_mutex: a job is being drawn
    std::string m_failure;    ///< under m_mutex
    double m_seconds = 0.0;   ///< under m_mutex
    int m_draws = 0;          ///< under m_mutex
    double m_fraction = 0.0;  ///< under m_mutex
    std::array<double, geometry::kNumSegments> m_bySegment{};  ///< under m_mutex
    std::vector<procedure::RecordedEvent> m_lesionEvents;      ///< under m_mutex
    std::atomic<double> m_latest{0.0};
    std::thread m_thread;
};

/// `loop`'s recording with `coverage`'s lesion events merged in (the loop's
/// own when there is no coverage): what is scored and stored.
[[nodiscard]] procedure::Recording recordingSeenBy(const procedure::ProcedureLoop& loop,
                                                   SessionCoverage* coverage);

/// Each lesion's triangles, in the case's order.
[[nodiscard]] std::vector<std::vector<int>> lesionTrianglesOf(const procedure::LesionView& lesions);

/// The coverage of a session of `loop` (built on `anatomy`) when the
/// renderer can run here; none (the scoring's geometric estimate and the
/// loop's lesion-in-view then) with the reason on `notices`.
[[nodiscard]] std::unique_ptr<SessionCoverage> tryCoverage(const geometry::ColonAnatomy& anatomy,
                                                           const procedure::ProcedureLoop& loop,
                                                           std::ostream& notices);

}  // namespace colonosim::cli
