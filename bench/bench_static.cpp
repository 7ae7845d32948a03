// Times the static equilibrium the procedure starts from (ProcedureLoop's
// constructor): the default colon under gravity and insufflation, from its
// rest shape to 1e-5 N, with the tangent system's conjugate gradients
// preconditioned by the assembled and factored -K+ (the default) and by its
// diagonal bound (Jacobi, the solver before). Arg 0: assembled, 1: diagonal.
// Compare the two rows of one run; counters: Newton iterations and residual.
//
// BM_ProcedureStart/seed: a whole ProcedureLoop construction (the colon
// built, its rest state solved, the contact and the scope set up) for the
// default colon (seed 0) and generated patients; BM_ProcedureStartThroughItself
// the same for tests/procedure/data/colon-through-itself.xml, generated seed 7
// kept as a file, whose colon overlaps itself at rest. Counters from the rest solve.

#include "bench/PatientFromSeed.h"
#include "case_generator/CaseReader.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/StaticSolver.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace colonosim;

void BM_StaticEquilibrium(benchmark::State& state)
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const auto preconditioning = state.range(0) == 0 ? physics::StaticPreconditioner::Assembled
                                                     : physics::StaticPreconditioner::Diagonal;
    physics::StaticResult result;
    for (auto _ : state) {
        state.PauseTiming();
        physics::ColonBody colon =
            physics::buildColonBody(anatomy, physics::TissueParameters{}, physics::EnvironmentParameters{},
                                    physics::StiffnessCalibration{});
        state.ResumeTiming();
        result = physics::solveStaticEquilibrium(colon.body, 1e-5, 1000, preconditioning);
        benchmark::DoNotOptimize(result);
    }
    state.counters["newton_iterations"] = result.iterations;
    state.counters["residual_N"] = result.residual;
    state.counters["converged"] = result.converged ? 1.0 : 0.0;
}
BENCHMARK(BM_StaticEquilibrium)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

/// Times ProcedureLoop's construction for one patient, with the counters of
/// its rest solve.
void timeStarts(benchmark::State& state, const geometry::AnatomyParameters& parameters,
                const procedure::ProcedureSettings& settings)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(parameters);
    physics::StaticResult rest;
    for (auto _ : state) {
        const procedure::ProcedureLoop loop(anatomy, settings);
        rest = loop.restSolve();
        benchmark::DoNotOptimize(rest);
    }
    state.counters["newton_iterations"] = rest.iterations;
    state.counters["factored_iterations"] = rest.factoredIterations;
    state.counters["cg_iterations"] = rest.conjugateGradientIterations;
    state.counters["residual_N"] = rest.residual;
    state.counters["stalled"] = rest.stalled ? 1.0 : 0.0;
}

void BM_ProcedureStart(benchmark::State& state)
{
    const bench::Patient patient = bench::patientFromSeed(static_cast<std::uint64_t>(state.range(0)));
    timeStarts(state, patient.anatomy, patient.settings);
}
BENCHMARK(BM_ProcedureStart)->Arg(0)->Arg(3)->Arg(15)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_ProcedureStartThroughItself(benchmark::State& state)
{
    const cases::ReadResult file = cases::readCaseFile(std::string(COLONOSIM_SOURCE_DIR) +
                                                       "/tests/procedure/data/colon-through-itself.xml");
    if (!file.ok()) {
        state.SkipWithError("tests/procedure/data/colon-through-itself.xml could not be read");
        return;
    }
    const cases::SceneSpec scene = cases::toScene(*file.value);
    timeStarts(state, scene.anatomy, cases::procedureSettings(scene));
}
BENCHMARK(BM_ProcedureStartThroughItself)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
