// Times one step of the default colon (default anatomy and tissue, gravity in
// left lateral position, insufflation, organs, the report's standard 2 N
// load held) for each integrator at its stable step (the Gershgorin bound of
// StabilityBound.h; backward Euler at 1 ms), one thread. items/s is steps
// per second. Target: >= 20,000 steps/s for symplectic Euler (the CSIRO
// paper took 10.6 ms per step).

#include "bench/report/BenchScene.h"
#include "bench/report/StepRate.h"

#include <benchmark/benchmark.h>

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
    const std::unique_ptr<colonosim::physics::Integrator> integrator = colonosim::physics::makeIntegrator(kind);
    s.load.apply(colon.body, s.load.rampTime);
    const colonosim::physics::Positions x0 = colon.body.positions();
    // Explicit Euler sits on its bound and drifts unstable over long runs:
    // restart from rest every kRestart steps (untimed) so no step is timed on
    // non-finite numbers.
    constexpr long kRestart = 2000;
    long count = 0;
    for (auto _ : state) {
        if (++count % kRestart == 0) {
            state.PauseTiming();
            colon.body.positions() = x0;
            colon.body.velocities().setZero();
            state.ResumeTiming();
        }
        integrator->step(colon.body, h);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(std::string(colonosim::physics::integratorName(kind)));
    state.counters["nodes"] = static_cast<double>(colon.body.numNodes());
    state.counters["step_us"] = h * 1e6;
    state.counters["finite"] = colon.body.positions().allFinite() ? 1.0 : 0.0;
}
BENCHMARK(BM_ColonStep)
    ->Arg(static_cast<int>(IntegratorKind::ExplicitEuler))
    ->Arg(static_cast<int>(IntegratorKind::SymplecticEuler))
    ->Arg(static_cast<int>(IntegratorKind::RungeKutta4))
    ->Arg(static_cast<int>(IntegratorKind::BackwardEuler))
    ->Unit(benchmark::kMicrosecond);

}  // namespace
