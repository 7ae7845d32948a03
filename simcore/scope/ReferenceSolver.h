#pragma once
/// \file
/// Reference static equilibrium of the discrete rod (DiscreteRod.h), the
/// accuracy reference for the chain solver. Unknowns are the absolute frames
/// C_0..C_{n-1}; the potential is
///
///     E = sum_k 1/2 Theta_k^T K_k Theta_k - sum_k l S_k . C_k e_3,
///     Theta_k = log(D_k^T C_{k-1}^T C_k),  S_k = sum_{j > k} f_j,
///
/// (bending and torsion energy minus the work of the dead nodal forces; node
/// torques add their virtual work T . omega). With body-frame increments
/// C_k <- C_k exp([delta_k]x) the exact gradient is
///
///     dE/d delta_k     += Jr^-1(Theta_k)^T K_k Theta_k,
///     dE/d delta_{k-1} -= (C_{k-1}^T C_k) Jr^-1(Theta_k)^T K_k Theta_k,
///     dE/d delta_k     -= l e_3 x (C_k^T S_k)   (and -C_k^T T for torques),
///
/// so the Hessian is block-tridiagonal. Newton's method solves with it, the
/// Hessian taken by central differences of the exact gradient with a 3-colour
/// pattern (18 gradient evaluations, O(n) each) and factorised by Eigen's
/// SparseLU; a backtracking line search on |gradient| and load stepping make
/// it robust from the straight rod. The converged gradient is exact, so the
/// answer is exact to the tolerance whatever the Hessian's rounding.

#include "simcore/scope/DiscreteRod.h"

namespace colonosim::scope {

struct ReferenceOptions {
    double tolerance = 1e-11;  ///< largest gradient component at convergence, N m
    int maxIterations = 60;    ///< Newton iterations per load step
    int loadSteps = 4;         ///< the loads are applied in this many increments
};

struct ReferenceResult {
    bool converged = false;
    int iterations = 0;         ///< Newton iterations, all load steps together
    double gradientNorm = 0.0;  ///< largest gradient component at the end, N m
};

/// Solves for equilibrium starting from the rod's current state; on return
/// rod.theta holds the equilibrium joint rotations and the rod is rebuilt.
ReferenceResult solveReference(DiscreteRod& rod, const ReferenceOptions& options = {});

}  // namespace colonosim::scope
