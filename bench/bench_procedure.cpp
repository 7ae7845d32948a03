// Times one full procedure loop step (issue target >= 10,000 steps/s, at
// least 5,000): the default colon (1,905 nodes) with its active region, the
// 80-node scope, contact on the whole wall and the coupling, one thread.
// The scene is first driven by the scripted expert for 3.5 s, so the scope
// sits in the rectum against the wall; each iteration is one more expert
// step from there (the scene evolves, as in a session).

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <benchmark/benchmark.h>

namespace {

using namespace colonosim;

void BM_ProcedureStep(benchmark::State& state)
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    for (int s = 0; s < 3500; ++s) {
        loop.step(expert.next(loop));
    }
    for (auto _ : state) {
        benchmark::DoNotOptimize(loop.step(expert.next(loop)));
    }
    state.counters["substeps"] = loop.tissue().substeps();
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ProcedureStep)->Unit(benchmark::kMicrosecond)->Iterations(2000);

}  // namespace
