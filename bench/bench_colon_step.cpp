// Times one step of the default colon (default anatomy and tissue, gravity in
// left lateral position, insufflation, organs, the report's standard 2 N
// load held) for each integrator at its stable step (the Gershgorin bound of
// StabilityBound.h; backward Euler at 1 ms), one thread. items/s is steps
// per second. Target: >= 20,000 steps/s for symplectic Euler (the CSIRO
// paper took 10.6 ms per step).

#include "bench/report/BenchScene.h"
#include "bench/report/StepRate.h"
#include "simcore/physics/ActiveRegion.h"
#include "simcore/physics/BackwardEuler.h"
#include "simcore/physics/TissueSimulation.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using colonosim::physics::IntegratorKind;

const colonosim::bench::BenchScene& scene()
{
    static const colonosim::bench::BenchScene instance = colonosim::bench::buildBenchScene();
    return instance;
}

void BM_ColonStep(benchmark::State& state)
{
    const auto kind = static_cast<IntegratorKind>(state.range(0));
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    const double h = colonosim::bench::benchStableStep(s, kind);
    const std::unique_ptr<colonosim::physics::Integrator> integrator =
        colonosim::physics::makeIntegrator(kind);
    s.load.apply(colon.body, s.load.rampTime);
    const colonosim::physics::Positions x0 = colon.body.positions();
    // Explicit Euler sits on its bound and drifts unstable over long runs:
    // restart from rest every kRestart steps (untimed) so no step is timed on
    // non-finite numbers.
    constexpr long kRestart = 2000;
    long count = 0;
    long cgIterations = 0;
    auto* implicit = dynamic_cast<colonosim::physics::BackwardEuler*>(integrator.get());
    for (auto _ : state) {
        if (++count % kRestart == 0) {
            state.PauseTiming();
            colon.body.positions() = x0;
            colon.body.velocities().setZero();
            state.ResumeTiming();
        }
        integrator->step(colon.body, h);
        benchmark::ClobberMemory();
        cgIterations += implicit != nullptr ? implicit->lastIterations() : 0;
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(std::string(colonosim::physics::integratorName(kind)));
    state.counters["nodes"] = static_cast<double>(colon.body.numNodes());
    state.counters["step_us"] = h * 1e6;
    state.counters["finite"] = colon.body.positions().allFinite() ? 1.0 : 0.0;
    if (implicit != nullptr) {
        state.counters["cg_per_step"] =
            static_cast<double>(cgIterations) / static_cast<double>(std::max<long>(1, count));
    }
}
BENCHMARK(BM_ColonStep)
    ->Arg(static_cast<int>(IntegratorKind::ExplicitEuler))
    ->Arg(static_cast<int>(IntegratorKind::SymplecticEuler))
    ->Arg(static_cast<int>(IntegratorKind::RungeKutta4))
    ->Arg(static_cast<int>(IntegratorKind::BackwardEuler))
    ->Unit(benchmark::kMicrosecond);

// The wall springs' force and damping alone (11,376 springs on the default
// colon, all awake), the colon step's largest term: items/s is springs per
// second.
void BM_WallSprings(benchmark::State& state)
{
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    s.load.apply(colon.body, s.load.rampTime);
    colonosim::physics::Velocities v = colonosim::physics::Velocities::Zero(3, colon.body.numNodes());
    for (Eigen::Index k = 0; k < v.size(); ++k) {
        v.data()[k] = 1e-3 * std::sin(static_cast<double>(k));  // every spring damped
    }
    colonosim::physics::Forces f = colonosim::physics::Forces::Zero(3, colon.body.numNodes());
    for (auto _ : state) {
        colon.springs->addForceAndDamping(colon.body.positions(), v, f);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * colon.springs->numSprings());
    state.counters["springs"] = colon.springs->numSprings();
    state.counters["finite"] = f.allFinite() ? 1.0 : 0.0;
}
BENCHMARK(BM_WallSprings)->Unit(benchmark::kMicrosecond);

/// The insufflation's pressure on every wall triangle (the default colon, all
/// awake), the colon step's second term: items/s is triangles per second.
void BM_Insufflation(benchmark::State& state)
{
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    colonosim::physics::Forces f = colonosim::physics::Forces::Zero(3, colon.body.numNodes());
    for (auto _ : state) {
        colon.insufflation->addForce(colon.body.positions(), f);
        benchmark::ClobberMemory();
    }
    const auto triangles = static_cast<double>(s.anatomy.physicsMesh.numTriangles());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(triangles));
    state.counters["triangles"] = triangles;
    state.counters["finite"] = f.allFinite() ? 1.0 : 0.0;
}
BENCHMARK(BM_Insufflation)->Unit(benchmark::kMicrosecond);

/// The organ projection, applied once per 1 ms loop step (not per substep).
void BM_OrganProjection(benchmark::State& state)
{
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            colon.body.projectConstraints(colon.body.positions(), colon.body.velocities()));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OrganProjection)->Unit(benchmark::kMicrosecond);

/// One whole 1 ms loop step as the procedure runs it: the substeps the
/// stability bound asks for, then the organ projection and the state check.
/// Real time needs <= 1000 us.
void BM_LoopStep(benchmark::State& state)
{
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    colonosim::physics::SteppingPolicy policy;
    policy.integrator = static_cast<IntegratorKind>(state.range(0));
    colonosim::physics::TissueSimulation simulation(colon.body, policy);
    s.load.apply(colon.body, s.load.rampTime);
    for (auto _ : state) {
        benchmark::DoNotOptimize(simulation.advance());
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(simulation.planNote());
    state.counters["substeps"] = simulation.substeps();
}
BENCHMARK(BM_LoopStep)
    ->Arg(static_cast<int>(IntegratorKind::SymplecticEuler))
    ->Arg(static_cast<int>(IntegratorKind::BackwardEuler))
    ->Unit(benchmark::kMicrosecond);

/// The same loop step with the active region: the colon settles for 0.5 s
/// (untimed) so that resting nodes fall asleep, then the standard push is
/// applied and each timed iteration is one loop step with the load held.
/// The figure depends on how far the disturbance has spread, so it is an
/// average over the benchmark's run (about a second of simulated time).
void BM_LoopStepActiveRegion(benchmark::State& state)
{
    const colonosim::bench::BenchScene& s = scene();
    colonosim::physics::ColonBody colon = s.makeBody();
    colonosim::physics::TissueSimulation simulation(colon.body, colonosim::physics::SteppingPolicy{});
    colonosim::physics::ActiveRegion region(colon.neighbours, colonosim::physics::SleepParameters{});
    simulation.setActiveRegion(&region);
    for (int step = 0; step < 500; ++step) {
        simulation.advance();
    }
    double awake = 0.0;
    for (auto _ : state) {
        colon.body.clearExternalForces();
        s.load.apply(colon.body, s.load.rampTime);
        benchmark::DoNotOptimize(simulation.advance());
        awake += region.numAwake();
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["awake_fraction"] =
        awake / static_cast<double>(state.iterations()) / static_cast<double>(colon.body.numNodes());
}
BENCHMARK(BM_LoopStepActiveRegion)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

}  // namespace
