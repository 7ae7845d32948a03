#include "bench/report/StepRate.h"

#include "bench/report/SceneRun.h"
#include "simcore/geometry/MeshMapping.h"
#include "simcore/physics/StabilityBound.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace colonosim::bench {

double benchStableStep(const BenchScene& scene, physics::IntegratorKind kind)
{
    if (kind == physics::IntegratorKind::BackwardEuler) {
        return 1e-3;
    }
    const physics::ColonBody colon = scene.makeBody();
    return physics::maxStableStep(kind, physics::estimateStability(colon.body));
}

double measureColonStepHz(const BenchScene& scene, physics::IntegratorKind kind, double minSeconds)
{
    physics::ColonBody colon = scene.makeBody();
    const std::unique_ptr<physics::Integrator> integrator = physics::makeIntegrator(kind);
    const double h = benchStableStep(scene, kind);
    scene.load.apply(colon.body, scene.load.rampTime);
    for (int s = 0; s < 3; ++s) {
        integrator->step(colon.body, h);
    }
    long steps = 0;
    const double start = processCpuSeconds();
    double elapsed = 0.0;
    while (elapsed < minSeconds) {
        for (int s = 0; s < 10; ++s) {
            integrator->step(colon.body, h);
        }
        steps += 10;
        elapsed = processCpuSeconds() - start;
    }
    return static_cast<double>(steps) / elapsed;
}

double measureMappingSeconds(const BenchScene& scene, int repeats)
{
    const geometry::MeshMapping mapping(scene.anatomy.physicsMesh, scene.anatomy.visualMesh.vertices);
    const RunResult run = runScene(scene, physics::IntegratorKind::BackwardEuler, 1e-3, 5e-3);
    const physics::Positions& deformed = run.stable ? run.finalPositions : scene.anatomy.physicsMesh.vertices;
    Eigen::Matrix3Xd visual(3, mapping.numVisualVertices());
    mapping.apply(deformed, visual);
    std::vector<double> times;
    times.reserve(static_cast<size_t>(repeats));
    for (int r = 0; r < repeats; ++r) {
        const double start = processCpuSeconds();
        mapping.apply(deformed, visual);
        times.push_back(processCpuSeconds() - start);
    }
    std::nth_element(times.begin(), times.begin() + repeats / 2, times.end());
    return times[static_cast<size_t>(repeats / 2)];
}

}  // namespace colonosim::bench
