#pragma once
/// \file
/// The stable explicit step, computed from the model.
///
/// Highest natural frequency: omega_max^2 <= max_i kRow_i / m_i (Gershgorin on
/// M^-1 K, reference/physical-parameters.md). Damping enters as the modal
/// damping rate c of each mode. Every damping force here is proportional to
/// a stiffness (c_e = beta_e k_e), so a mode of frequency omega has
/// c in [beta_min omega^2, min(beta_max omega^2, C)], with beta the node-wise
/// ratio cRow/kRow and C = max_i cRow_i / m_i.
///
/// For the scalar test equation x'' = -omega^2 x - c x' each integrator has an
/// amplification matrix A(h omega, h c); a step h is stable when the spectral
/// radius of A is at most 1 for every admissible (omega, c). maxStableStep()
/// finds the largest such h by bisection over a dense sample of omega. It
/// reproduces the closed forms: symplectic Euler h < 2/omega undamped and
/// omega h < 2(sqrt(1 + zeta^2) - zeta) damped; forward Euler h < 2 zeta/omega
/// (none undamped); RK4 h < 2 sqrt(2)/omega undamped; backward Euler: any h.

#include "simcore/physics/Integrator.h"
#include "simcore/physics/TissueBody.h"

namespace colonosim::physics {

struct StabilityEstimate {
    double omegaMax = 0.0;        ///< Gershgorin bound on the highest natural frequency, rad/s
    double betaMin = 0.0;         ///< smallest damping-to-stiffness ratio, s
    double betaMax = 0.0;         ///< largest damping-to-stiffness ratio, s
    double dampingRateMax = 0.0;  ///< Gershgorin bound C on M^-1 D, 1/s
    int stiffestNode = -1;        ///< node that sets omegaMax
};

/// Gershgorin estimate over the body's integrated nodes.
[[nodiscard]] StabilityEstimate estimateStability(const TissueBody& body);
/// The same with caller-owned row-sum scratch (no allocation once sized).
[[nodiscard]] StabilityEstimate estimateStability(const TissueBody& body, Eigen::VectorXd& kRow,
                                                  Eigen::VectorXd& cRow);

/// Spectral radius of the integrator's amplification matrix for
/// x'' = -omega^2 x - c x' at step h.
[[nodiscard]] double amplification(IntegratorKind kind, double omega, double c, double h);

/// Largest stable step (s) for the estimate; +infinity for backward Euler,
/// 0 when no positive step is stable (forward Euler without damping).
[[nodiscard]] double maxStableStep(IntegratorKind kind, const StabilityEstimate& estimate);

/// Highest natural frequency of the linearised body (rad/s), from the dense
/// eigenproblem of M^-1/2 (-K) M^-1/2 over the integrated nodes. For
/// validation on small bodies (up to 1,500 nodes).
[[nodiscard]] double exactOmegaMax(const TissueBody& body);

/// Highest natural frequency by power iteration, matrix-free, for bodies of
/// any size; converges from below.
[[nodiscard]] double powerIterationOmegaMax(const TissueBody& body, int iterations);

/// The highest mode as power iteration finds it: its frequency and the
/// damping it gets, the Rayleigh quotients of M^-1/2 K M^-1/2 and
/// M^-1/2 D M^-1/2 at the converged vector (the mode's own damping where D
/// is proportional to K; with the wall's transverse damping, the damping of
/// that shape).
struct TopMode {
    double omega = 0.0;         ///< rad/s
    double dampingRate = 0.0;   ///< c of x'' = -omega^2 x - c x', 1/s
    double dampingRatio = 0.0;  ///< zeta = c / (2 omega)
};
[[nodiscard]] TopMode powerIterationTopMode(const TissueBody& body, int iterations);

}  // namespace colonosim::physics
