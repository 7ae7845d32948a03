#pragma once
/// \file
/// Static equilibrium f(x) = 0 of a tissue body by a quasi-Newton method:
/// each iteration solves (-K+) dx = f(x) by conjugate gradients over the
/// integrated nodes, preconditioned by -K+ itself assembled by probing and
/// factored (TangentPreconditioner.h; by its diagonal bound where that
/// factorisation fails), then x += dx (step halved while the
/// residual grows; when 20 halvings do not lower it, or three iterations in
/// a row each lower it by less than 1%, the solve stops there, stalled, at
/// the best state found). K+ is the definite stiffness of the symmetric terms, so
/// where springs are compressed, tethers slack or insufflation loads the wall
/// (its Jacobian is left out) convergence is linear rather than quadratic:
/// about 80 iterations to 1e-9 N on a 480-node tube. Damping plays no part
/// (v = 0). Used by the calibration and as a reference state.

#include "simcore/physics/TissueBody.h"

namespace colonosim::physics {

struct StaticResult {
    bool converged = false;
    int iterations = 0;
    double residual = 0.0;       ///< largest nodal force norm at the end, N
    bool stalled = false;        ///< stopped because the Newton steps no longer lowered the residual (by 1%)
    int factoredIterations = 0;  ///< iterations preconditioned by the assembled factor
    int conjugateGradientIterations = 0;  ///< over all the iterations' tangent solves
};

/// How the tangent system's conjugate gradients are preconditioned.
enum class StaticPreconditioner {
    Assembled,  ///< -K+ probed and factored at each iteration (the default)
    Diagonal,   ///< the diagonal bound of -K+ (Jacobi): no setup, many more iterations
};

/// Stops when every integrated node's net force is below `forceTolerance` (N).
StaticResult solveStaticEquilibrium(TissueBody& body, double forceTolerance, int maxIterations = 300,
                                    StaticPreconditioner preconditioning = StaticPreconditioner::Assembled);

}  // namespace colonosim::physics
