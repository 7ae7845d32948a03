#include "trainer_ui/app/SimulationRunner.h"

#include "trainer_ui/cli/LoopPacer.h"

#include "simcore/devices/HdcOperator.h"
#include "simcore/render/LensSoiling.h"

#include <algorithm>
#include <chrono>
#include <iostream>

namespace colonosim::app {

namespace {
using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}
}  // namespace

SimulationRunner::SimulationRunner(std::shared_ptr<const ProcedureScene> scene,
                                   std::unique_ptr<procedure::Operator> driver, const RunnerOptions& options)
    : m_scene(std::move(scene)), m_driver(std::move(driver)), m_options(options)
{
    m_paused.store(options.startPaused);
    m_speed.store(std::clamp(options.speed, 0.25, 4.0));
    m_thread = std::jthread([this](std::stop_token stop) { run(std::move(stop)); });
}

SimulationRunner::~SimulationRunner()
{
    m_thread.request_stop();
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

void SimulationRunner::setSpeed(double speed)
{
    m_speed.store(std::clamp(speed, 0.25, 4.0), std::memory_order_release);
}

const procedure::ProcedureLoop* SimulationRunner::loop() const
{
    return finished() ? m_loop.get() : nullptr;
}

std::optional<double> SimulationRunner::mucosaSeen()
{
    if (!finished() || !m_coverage) {
        return std::nullopt;
    }
    return m_coverage->finalFraction();
}

procedure::Recording SimulationRunner::recording()
{
    if (!finished() || !m_loop) {
        throw std::logic_error("SimulationRunner::recording: the procedure has not finished");
    }
    return cli::recordingSeenBy(*m_loop, m_coverage.get());
}

void SimulationRunner::publish(Snapshot::State state, double physicsRate)
{
    Snapshot& out = m_snapshots.back();
    out.state = state;
    out.failure = m_failure;
    out.physicsRate = physicsRate;
    out.mucosaSeen = m_coverage ? m_coverage->latestFraction() : -1.0;
    if (m_loop) {
        const procedure::ProcedureLoop& loop = *m_loop;
        out.frame = loop.lastFrame();
        out.frame.time = loop.time();
        out.tip = loop.outputs().tip;
        out.wall = loop.colon().body.positions();
        out.bleedingMarks = loop.bleedingMarks();
        out.scopeNodes.assign(loop.scope().nodePositions().begin(), loop.scope().nodePositions().end());
        out.loopSegment.reset();
        if (loop.loops().current() != procedure::LoopKind::None) {
            out.loopSegment = loop.loops().signals().segment;
        }
        out.lensSoiling = m_lensSoiling;
        out.speed = m_speed.load(std::memory_order_acquire);
        out.targetRate = out.speed / loop.trace().loopStep;
    }
    m_snapshots.publish();
}

void SimulationRunner::run(std::stop_token stop)
{
    publish(Snapshot::State::Preparing, 0.0);
    try {
        m_loop = std::make_unique<procedure::ProcedureLoop>(m_scene->anatomy, m_scene->settings);
    } catch (const std::exception& error) {
        m_failure = std::string("the procedure could not start: ") + error.what();
        publish(Snapshot::State::Failed, 0.0);
        m_finished.store(true, std::memory_order_release);
        return;
    }
    procedure::ProcedureLoop& loop = *m_loop;
    if (m_options.coverage) {
        m_coverage = cli::tryCoverage(m_scene->anatomy, loop, std::cerr);
    }
    auto* hdc = dynamic_cast<devices::HdcOperator*>(m_driver.get());
    render::LensSoiling lens{render::RenderParameters{}};
    const double dt = loop.trace().loopStep;
    const double publishInterval = 1.0 / kPublishRate;

    // Pacing: simulated time follows the wall clock times the speed (LoopPacer.h).
    const Clock::time_point origin = Clock::now();
    cli::LoopPacer pacer;
    double anchorSpeed = m_speed.load();
    pacer.restart(loop.time(), 0.0, anchorSpeed);
    bool wasPaused = m_paused.load();
    bool seeking = m_options.seekTo > 0.0;
    bool pausePublished = false;
    Clock::time_point windowStart = origin;
    long windowSteps = 0;
    double rate = 0.0;
    Clock::time_point lastPublish = origin - std::chrono::seconds(1);

    const auto ended = [&] {
        return loop.time() + 0.5 * dt >= m_options.maxTime || m_driver->finished() ||
               m_endRequested.load(std::memory_order_acquire);
    };
    while (!stop.stop_requested() && !ended()) {
        const bool paused = m_paused.load(std::memory_order_acquire) && !seeking;
        const double speed = m_speed.load(std::memory_order_acquire);
        Clock::time_point now = Clock::now();
        if (paused != wasPaused || speed != anchorSpeed) {
            pacer.restart(loop.time(), secondsBetween(origin, now), speed);
            anchorSpeed = speed;
            wasPaused = paused;
            windowStart = now;
            windowSteps = 0;
        }
        if (paused) {
            if (!pausePublished) {  // a paused loop does not change: one snapshot says so
                publish(Snapshot::State::Paused, 0.0);
                pausePublished = true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            continue;
        }
        if (m_driver->keepsTime()) {
            // The device sets the pace (one step per frame); the pacing
            // follows, so the wall clock takes over if it stops.
            pacer.restart(loop.time(), secondsBetween(origin, now), speed);
        } else if (!seeking) {
            const double wall = secondsBetween(origin, now);
            const double due = pacer.dueAt(loop.time(), dt, wall);
            if (due > wall + 1e-9 / speed) {
                std::this_thread::sleep_until(
                    origin + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(due)));
                continue;
            }
        }
        pausePublished = false;
        if (hdc != nullptr) {
            hdc->recordConnection(loop);
        }
        loop.step(m_driver->next(loop), hdc);  // the HDC is answered as soon as the scope has its load
        if (m_coverage) {
            m_coverage->observe(loop);
        }
        const procedure::ProcedureFrame& frame = loop.lastFrame();
        lens.update(dt, frame.lensWallDistance, (frame.input.buttons & procedure::kWater) != 0);
        m_lensSoiling = lens.amount();
        ++windowSteps;
        now = Clock::now();
        const double window = secondsBetween(windowStart, now);
        if (window >= 0.5) {
            rate = static_cast<double>(windowSteps) / window;
            windowStart = now;
            windowSteps = 0;
        }
        if (seeking && loop.time() + 0.5 * dt >= m_options.seekTo) {
            seeking = false;
            m_paused.store(true, std::memory_order_release);
            publish(Snapshot::State::Paused, rate);
            pausePublished = true;
            lastPublish = now;
            continue;
        }
        if (secondsBetween(lastPublish, now) >= publishInterval) {
            publish(Snapshot::State::Running, rate);
            lastPublish = now;
        }
    }
    publish(Snapshot::State::Finished, rate);
    m_finished.store(true, std::memory_order_release);
}

}  // namespace colonosim::app
