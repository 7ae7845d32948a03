#include "trainer_ui/cli/SessionCoverage.h"

#include "simcore/render/CoverageTracker.h"
#include "simcore/render/OffscreenContext.h"
#include "simcore/render/RenderParameters.h"

#include <chrono>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace colonosim::cli {

SessionCoverage::SessionCoverage(const geometry::ColonAnatomy& anatomy,
                                 std::vector<std::vector<int>> lesionTriangles)
    : m_interval(render::RenderParameters{}.coverageInterval)
{
    m_thread = std::thread([this, &anatomy, triangles = std::move(lesionTriangles)]() mutable {
        work(anatomy, std::move(triangles));
    });
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_ready; });
    if (!m_failure.empty()) {
        lock.unlock();
        m_thread.join();
        throw std::runtime_error(m_failure);
    }
}

SessionCoverage::~SessionCoverage()
{
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_changed.notify_all();
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

void SessionCoverage::work(const geometry::ColonAnatomy& anatomy,
                           std::vector<std::vector<int>> lesionTriangles)
{
    const size_t numLesions = lesionTriangles.size();
    // The context is current on this thread only: made, used and destroyed here.
    std::unique_ptr<render::OffscreenContext> context;
    std::unique_ptr<render::CoverageTracker> tracker;
    try {
        context = std::make_unique<render::OffscreenContext>(1, 1);
        std::vector<geometry::Segment> triangleSegment;
        triangleSegment.reserve(anatomy.physicsMesh.triangles.size());
        for (const auto& t : anatomy.physicsMesh.triangles) {
            triangleSegment.push_back(anatomy.physicsNodes[static_cast<size_t>(t[0])].segment);
        }
        tracker = std::make_unique<render::CoverageTracker>(
            context->gl(), anatomy.physicsMesh, std::move(triangleSegment), render::RenderParameters{});
        tracker->setLesionTriangles(std::move(lesionTriangles));
    } catch (const std::exception& error) {
        const std::lock_guard lock(m_mutex);
        m_failure = error.what();
        m_ready = true;
        m_changed.notify_all();
        return;
    }
    {
        const std::lock_guard lock(m_mutex);
        m_ready = true;
    }
    m_changed.notify_all();
    std::vector<bool> shown;  // lesions on screen at the previous draw; empty before the first
    for (;;) {
        Job job;
        {
            std::unique_lock lock(m_mutex);
            m_changed.wait(lock, [this] { return m_stop || !m_jobs.empty(); });
            if (m_jobs.empty()) {
                break;  // stopped with nothing left to draw
            }
            job = std::move(m_jobs.front());
            m_jobs.pop_front();
            m_busy = true;
        }
        const auto start = std::chrono::steady_clock::now();
        tracker->observe(job.positions, job.pose);
        const double fraction = tracker->fractionSeen();
        std::array<double, geometry::kNumSegments> bySegment{};
        for (size_t k = 0; k < bySegment.size(); ++k) {
            bySegment[k] = tracker->fractionSeen(static_cast<geometry::Segment>(k));
        }
        const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_latest.store(fraction, std::memory_order_relaxed);
        std::vector<procedure::RecordedEvent> events;
        const std::vector<bool>& now = tracker->lesionsInView();
        for (size_t k = 0; k < numLesions; ++k) {
            if (shown.empty() || now[k] != shown[k]) {  // every lesion's state at the first draw
                events.push_back(
                    {job.time,
                     now[k] ? procedure::EventKind::LesionOnScreen : procedure::EventKind::LesionOffScreen,
                     procedure::lesionName(static_cast<int>(k))});
            }
        }
        shown = now;
        {
            const std::lock_guard lock(m_mutex);
            m_lesionEvents.insert(m_lesionEvents.end(), events.begin(), events.end());
            m_busy = false;
            m_fraction = fraction;
            m_bySegment = bySegment;
            m_seconds += took;
            ++m_draws;
        }
        m_changed.notify_all();
    }
    tracker.reset();  // its OpenGL objects go while the context still exists
}

void SessionCoverage::observe(const procedure::ProcedureLoop& loop)
{
    if (loop.time() + 1e-9 < m_next) {
        return;
    }
    m_next = loop.time() + m_interval;
    const scope::TipPose& tip = loop.outputs().tip;
    {
        std::unique_lock lock(m_mutex);
        // A loop far faster than the draws (a scripted run in a sleeping
        // colon) waits rather than queue without bound; nothing is dropped.
        m_changed.wait(lock, [this] { return m_jobs.size() < kMaxQueued; });
        m_jobs.push_back({loop.time(), loop.colon().body.positions(), {tip.position, tip.rotation}});
    }
    m_changed.notify_all();
}

std::unique_lock<std::mutex> SessionCoverage::drained()
{
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_jobs.empty() && !m_busy; });
    return lock;
}

double SessionCoverage::finalFraction()
{
    const std::unique_lock lock = drained();
    return m_fraction;
}

std::array<double, geometry::kNumSegments> SessionCoverage::finalBySegment()
{
    const std::unique_lock lock = drained();
    return m_bySegment;
}

std::vector<procedure::RecordedEvent> SessionCoverage::lesionEvents()
{
    const std::unique_lock lock = drained();
    return m_lesionEvents;
}

double SessionCoverage::drawSeconds() const
{
    const std::lock_guard lock(m_mutex);
    return m_seconds;
}

int SessionCoverage::draws() const
{
    const std::lock_guard lock(m_mutex);
    return m_draws;
}

procedure::Recording recordingSeenBy(const procedure::ProcedureLoop& loop, SessionCoverage* coverage)
{
    procedure::Recording recording = loop.recording();
    if (coverage != nullptr) {
        recording.mergeEvents(coverage->lesionEvents());
    }
    return recording;
}

std::vector<std::vector<int>> lesionTrianglesOf(const procedure::LesionView& lesions)
{
    std::vector<std::vector<int>> out;
    for (int k = 0; k < lesions.count(); ++k) {
        out.push_back(lesions.triangles(k));
    }
    return out;
}

std::unique_ptr<SessionCoverage> tryCoverage(const geometry::ColonAnatomy& anatomy,
                                             const procedure::ProcedureLoop& loop, std::ostream& notices)
{
    try {
        return std::make_unique<SessionCoverage>(anatomy, lesionTrianglesOf(loop.lesions()));
    } catch (const std::exception& error) {
        notices << "coverage: the renderer cannot run here (" << error.what()
                << "); % mucosa visualised is the geometric estimate, and a lesion counts as in view "
                   "without the renderer's occlusion test\n";
        return nullptr;
    }
}

}  // namespace colonosim::cli
