#include "bench/report/ActiveRegionStudy.h"

#include "bench/report/SceneRun.h"
#include "simcore/physics/ActiveRegion.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TissueSimulation.h"

#include <cmath>
#include <ostream>

namespace colonosim::bench {

namespace {
struct LoopRun {
    physics::Positions positions;
    double cpu = 0.0;
    double awakeSum = 0.0;
    double finalAwake = 1.0;
    long steps = 0;
};

LoopRun runLoop(const BenchScene& scene, double duration, bool withRegion)
{
    physics::ColonBody colon = scene.makeBody();
    // Start at rest in the unloaded equilibrium, so only the load moves the colon.
    (void)physics::solveStaticEquilibrium(colon.body, 1e-7, 100);
    physics::SteppingPolicy policy;
    policy.integrator = physics::IntegratorKind::SymplecticEuler;
    // The default budget (32 substeps) is below what this colon's bound needs,
    // so the policy would fall back to backward Euler; allow enough substeps.
    policy.maxSubsteps = 64;
    physics::TissueSimulation simulation(colon.body, policy);
    physics::ActiveRegion region(colon.neighbours, physics::SleepParameters{});
    if (withRegion) {
        simulation.setActiveRegion(&region);
    }
    const auto steps = std::lround(duration / policy.loopStep);
    const double n = colon.body.numNodes();
    LoopRun run;
    const double start = processCpuSeconds();
    for (long s = 0; s < steps; ++s) {
        scene.load.apply(colon.body, simulation.time());
        simulation.advance();
        run.finalAwake = withRegion ? region.numAwake() / n : 1.0;
        run.awakeSum += run.finalAwake;
    }
    run.cpu = processCpuSeconds() - start;
    run.steps = steps;
    run.positions = colon.body.positions();
    return run;
}
}  // namespace

ActiveRegionResult runActiveRegionStudy(const BenchScene& scene, double duration, std::ostream& log)
{
    const LoopRun full = runLoop(scene, duration, false);
    const LoopRun active = runLoop(scene, duration, true);
    const PositionError error = positionError(active.positions, full.positions);
    ActiveRegionResult result;
    result.duration = duration;
    result.cpuFull = full.cpu;
    result.cpuActive = active.cpu;
    result.speedup = active.cpu > 0.0 ? full.cpu / active.cpu : NAN;
    result.rmsError = error.rms;
    result.maxError = error.max;
    result.awakeFraction = active.steps > 0 ? active.awakeSum / static_cast<double>(active.steps) : 1.0;
    result.finalAwakeFraction = active.finalAwake;
    log << "active region: " << duration << " s simulated; full " << full.cpu << " s CPU, active "
        << active.cpu << " s CPU (speed-up " << result.speedup << "); awake fraction mean "
        << result.awakeFraction << ", final " << result.finalAwakeFraction << "; error rms " << error.rms
        << " m, max " << error.max << " m\n";
    return result;
}

}  // namespace colonosim::bench
