#pragma once
/// \file
/// The rate of full procedure loop steps, as bench_procedure times it: the
/// default colon (geometry::buildProceduralColon with default anatomy) in a
/// ProcedureLoop with default settings, driven by the scripted expert
/// (procedure::expertStyle()) for `warmupSteps` steps (3,500 in the full
/// report: 3.5 s, the scope then against the rectal wall), then timed over
/// `timedSteps` more expert steps (the scene evolves, as in a session).
/// Uses only the loop's public stepping interface. CPU time, one thread.

namespace colonosim::bench {

struct ProcedureRate {
    double stepHz = 0.0;  ///< loop steps per CPU second
    int substeps = 0;     ///< tissue substeps per loop step at the end
    int warmupSteps = 0;
    int timedSteps = 0;
};

[[nodiscard]] ProcedureRate measureProcedureStepRate(int warmupSteps, int timedSteps);

}  // namespace colonosim::bench
