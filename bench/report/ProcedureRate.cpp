#include "bench/report/ProcedureRate.h"

#include "bench/report/SceneRun.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

namespace colonosim::bench {

ProcedureRate measureProcedureStepRate(int warmupSteps, int timedSteps)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    for (int s = 0; s < warmupSteps; ++s) {
        loop.step(expert.next(loop));
    }
    const double start = processCpuSeconds();
    for (int s = 0; s < timedSteps; ++s) {
        loop.step(expert.next(loop));
    }
    const double cpu = processCpuSeconds() - start;
    ProcedureRate rate;
    rate.stepHz = cpu > 0.0 ? static_cast<double>(timedSteps) / cpu : 0.0;
    rate.substeps = loop.tissue().substeps();
    rate.warmupSteps = warmupSteps;
    rate.timedSteps = timedSteps;
    return rate;
}

}  // namespace colonosim::bench
