#pragma once
/// \file
/// The chain-based beam solver of de Visser et al. 2010 (seed 001, section
/// 2.5, eqs 1-7), after Pai's chain approach: no matrix is assembled or
/// inverted. One iteration:
///
/// 1. (eq 1) From the tip to the base, the external load on each node is the
///    load downstream of it plus its own: F_k = F_{k+1} + f_k, and the moment
///    about node k, M_k = M_{k+1} + (x_{k+1} - x_k) x F_{k+1} (+ node torques).
/// 2. (eqs 2-3) The net load on joint k in its local frame is
///    C_k^T M_k - K_k Theta_k.
/// 3. (eqs 4-5) Theta_k += w (C_k^T M_k - K_k Theta_k) / K_k, with the
///    under-relaxation w (w = 1 is the paper's eq 4; for a tip-loaded
///    cantilever it fails to settle at PL^2/EI = 4, where w = 0.5 converges
///    in 14 iterations; 0.5 fails at PL^2/EI = 8. See ScopeParameters).
/// 4. (eqs 6-7) Positions and frames are rebuilt from the base to the tip.
///
/// The fixed point is K_k Theta_k = C_k^T M_k: the static equilibrium of the
/// discrete rod (identical to the reference solver's for loads in a plane;
/// in 3-D the two differ by O(Theta_k^2) per joint because the chain uses the
/// rotation vector where the energy gradient carries Jr^-1(Theta_k)^T).
/// Theta is warm-started from the previous call, as in the paper.

#include "simcore/scope/DiscreteRod.h"

namespace colonosim::scope {

/// Base load of the chain (eq 1 at the clamp): the sum of the external
/// forces and their moment about the clamp point, world frame.
struct BaseLoad {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< N
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N m, about basePosition
};

/// Runs `iterations` chain iterations on `rod` (no allocation). Returns the
/// largest |dTheta| of the last iteration, rad.
double solveChain(DiscreteRod& rod, int iterations, double relaxation);

/// Eq 1 at the clamp for the current positions.
[[nodiscard]] BaseLoad baseLoad(const DiscreteRod& rod);

}  // namespace colonosim::scope
