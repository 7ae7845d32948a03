#pragma once
/// \file
/// Static equilibrium f(x) = 0 of a tissue body by Newton's method: each
/// iteration solves (-K+) dx = f(x) by Jacobi-preconditioned conjugate
/// gradients over the integrated nodes, then x += dx (step halved while the
/// residual grows). Damping plays no part (v = 0). Used by the calibration
/// and as a reference state.

#include "simcore/physics/TissueBody.h"

namespace colonosim::physics {

struct StaticResult {
    bool converged = false;
    int iterations = 0;
    double residual = 0.0;  ///< largest nodal force norm at the end, N
};

/// Stops when every integrated node's net force is below `forceTolerance` (N).
StaticResult solveStaticEquilibrium(TissueBody& body, double forceTolerance, int maxIterations = 50);

}  // namespace colonosim::physics
