// Times one full procedure loop step (issue target >= 10,000 steps/s, at
// least 5,000): the default colon (1,905 nodes) with its active region, the
// 80-node scope, contact on the whole wall and the coupling, one thread.
// The scene is first driven by the scripted expert for the argument's
// milliseconds: 1000 leaves the scope in the rectum with most of the colon
// asleep (the next 2 s stay so); 3500 puts it against the rectal wall just
// before it enters the sigmoid, where the whole colon wakes within 2 s;
// 10000 puts it in the mid-sigmoid, pushing the sigmoid on its mesentery;
// 60000 has it past the splenic flexure with most of the shaft on the wall,
// where the contact coupling's dense solve over the nodes in contact costs
// most (its warm-up takes a few minutes).
// Each iteration is one more expert step (the scene evolves, as in a session).

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
    for (int s = 0; s < state.range(0); ++s) {
        loop.step(expert.next(loop));
    }
    for (auto _ : state) {
        benchmark::DoNotOptimize(loop.step(expert.next(loop)));
    }
    state.counters["substeps"] = loop.tissue().substeps();
    state.counters["integrated_nodes"] = static_cast<double>(loop.colon().body.integratedNodes().size());
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ProcedureStep)
    ->Arg(1000)
    ->Arg(3500)
    ->Arg(10000)
    ->Arg(60000)
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(2000);

}  // namespace
