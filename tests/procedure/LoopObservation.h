#pragma once
/// \file
/// What the procedure-loop tests observe of a running loop: the default
/// colon they share, and a summary of a run (finite state, peak handle force)
/// kept step by step.

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <cmath>

namespace colonosim::looptest {

/// The default procedural colon, built once per test binary.
inline const geometry::ColonAnatomy& defaultColon()
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return anatomy;
}

/// The redundant sigmoid of the loop tests: 66 cm, as in incomplete
/// examinations, its mesocolon 8.9 cm (one SD above the mean).
inline geometry::AnatomyParameters redundantSigmoid()
{
    geometry::AnatomyParameters redundant;
    redundant.sigmoidLength = 0.66;
    redundant.sigmoidMesenteryHeight = 0.089;
    return redundant;
}

struct RunSummary {
    double peakHandleForce = 0.0;  ///< N
    bool finite = true;            ///< every output, scope node and wall node stayed finite
};

inline void observe(const procedure::ProcedureLoop& loop, RunSummary& summary)
{
    const procedure::ProcedureOutputs& out = loop.outputs();
    summary.finite = summary.finite && std::isfinite(out.handleForce) && std::isfinite(out.handleTorque) &&
                     out.tip.position.allFinite() && loop.colon().body.positions().allFinite();
    summary.peakHandleForce = std::max(summary.peakHandleForce, std::abs(out.handleForce));
    for (const Eigen::Vector3d& p : loop.scope().nodePositions()) {
        summary.finite = summary.finite && p.allFinite();
    }
}

/// Steps the loop with `driver` for `steps` steps or until it has finished.
inline RunSummary runOperator(procedure::ProcedureLoop& loop, procedure::Operator& driver, int steps)
{
    RunSummary summary;
    for (int s = 0; s < steps && !driver.finished(); ++s) {
        loop.step(driver.next(loop));
        observe(loop, summary);
    }
    return summary;
}

}  // namespace colonosim::looptest
