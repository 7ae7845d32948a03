#include "bench/report/SceneRun.h"

#include <cmath>
#include <ctime>

namespace colonosim::bench {

double processCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

namespace {
bool stateIsSane(const physics::TissueBody& body)
{
    const double limit2 = kUnstableSpeed * kUnstableSpeed;
    for (const int i : body.integratedNodes()) {
        const double speed2 = body.velocities().col(i).squaredNorm();
        if (!std::isfinite(speed2) || !(speed2 <= limit2) || !body.positions().col(i).allFinite()) {
            return false;
        }
    }
    return true;
}
}  // namespace

RunResult runScene(const BenchScene& scene, physics::IntegratorKind kind, double requestedStep,
                   double duration)
{
    physics::ColonBody colon = scene.makeBody();
    physics::TissueBody& body = colon.body;
    const std::unique_ptr<physics::Integrator> integrator = physics::makeIntegrator(kind);
    // Whole steps ending exactly at `duration`: h shrinks by less than one part in numSteps.
    const long numSteps = std::max(1L, static_cast<long>(std::ceil(duration / requestedStep - 1e-9)));
    const double h = duration / static_cast<double>(numSteps);
    constexpr long kCheckEvery = 10;
    constexpr double kLoopStep = 1e-3;  // s

    RunResult result;
    result.step = h;
    const double start = processCpuSeconds();
    for (long s = 0; s < numSteps; ++s) {
        scene.load.apply(body, (static_cast<double>(s) + 0.5) * h);
        integrator->step(body, h);
        // Organs are projected once per 1 ms loop step, as in TissueSimulation.
        if (std::floor(static_cast<double>(s + 1) * h / kLoopStep + 1e-9) >
            std::floor(static_cast<double>(s) * h / kLoopStep + 1e-9)) {
            body.projectConstraints(body.positions(), body.velocities());
        }
        ++result.steps;
        if ((s + 1) % kCheckEvery == 0 || s + 1 == numSteps) {
            if (!stateIsSane(body)) {
                result.stable = false;
                break;
            }
        }
    }
    result.cpuSeconds = processCpuSeconds() - start;
    result.simulatedTime = static_cast<double>(result.steps) * h;
    if (result.stable) {
        result.finalPositions = body.positions();
    }
    return result;
}

PositionError positionError(const physics::Positions& a, const physics::Positions& b)
{
    PositionError error;
    if (a.cols() == 0 || a.cols() != b.cols()) {
        error.rms = error.max = NAN;
        return error;
    }
    double sum2 = 0.0;
    for (Eigen::Index i = 0; i < a.cols(); ++i) {
        const double d = (a.col(i) - b.col(i)).norm();
        sum2 += d * d;
        error.max = std::max(error.max, d);
    }
    error.rms = std::sqrt(sum2 / static_cast<double>(a.cols()));
    return error;
}

}  // namespace colonosim::bench
