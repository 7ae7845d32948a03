#include "trainer_ui/cli/SessionCoverage.h"

#include "simcore/render/CoverageTracker.h"
#include "simcore/render/OffscreenContext.h"
#include "simcore/render/RenderParameters.h"

#include <chrono>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace colonosim::cli {

SessionCoverage::SessionCoverage(const geometry::ColonAnatomy& anatomy)
    : m_interval(render::RenderParameters{}.coverageInterval)
{
    m_thread = std::thread([this, &anatomy] { work(anatomy); });
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

void SessionCoverage::work(const geometry::ColonAnatomy& anatomy)
{
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
        const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_latest.store(fraction, std::memory_order_relaxed);
        {
            const std::lock_guard lock(m_mutex);
            m_busy = false;
            m_fraction = fraction;
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
        m_jobs.push_back({loop.colon().body.positions(), {tip.position, tip.rotation}});
    }
    m_changed.notify_all();
}

double SessionCoverage::finalFraction()
{
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_jobs.empty() && !m_busy; });
    return m_fraction;
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

std::unique_ptr<SessionCoverage> tryCoverage(const geometry::ColonAnatomy& anatomy, std::ostream& notices)
{
    try {
        return std::make_unique<SessionCoverage>(anatomy);
    } catch (const std::exception& error) {
        notices << "coverage: the renderer cannot run here (" << error.what()
                << "); % mucosa visualised is the geometric estimate\n";
        return nullptr;
    }
}

}  // namespace colonosim::cli
