#pragma once
/// \file
/// Backward (implicit) Euler, linearised once per step (Baraff & Witkin 1998):
///   (M - h D - h^2 K+) dv = h (f(x, v) + h K+ v),  v' = v + dv,  x' = x + h v',
/// with K+ the definite stiffness of the symmetric terms and non-symmetric
/// terms (insufflation) taken explicitly in f. The system is solved
/// matrix-free by conjugate gradients with a Jacobi preconditioner built
/// from the Gershgorin row sums, warm-started from the previous dv.
/// Unconditionally stable for linear damped systems, with numerical damping.

#include "simcore/physics/Integrator.h"

namespace colonosim::physics {

class BackwardEuler final : public Integrator {
public:
    [[nodiscard]] IntegratorKind kind() const override { return IntegratorKind::BackwardEuler; }
    void step(TissueBody& body, double h) override;

    /// Relative residual at which CG stops (1).
    void setTolerance(double relativeResidual) { m_tolerance = relativeResidual; }
    void setMaxIterations(int iterations) { m_maxIterations = iterations; }
    [[nodiscard]] int lastIterations() const { return m_lastIterations; }
    [[nodiscard]] double lastResidual() const { return m_lastResidual; }

private:
    /// Sorts the symmetric terms into those that froze their system at the
    /// body's positions for step h and those that did not.
    void linearize(TissueBody& body, double h);
    /// out = (M - h D - h^2 K+) y on the integrated nodes.
    void applySystem(const TissueBody& body, double h, const Eigen::Matrix3Xd& y, Eigen::Matrix3Xd& out);

    /// Relative CG residual: 1e-6 keeps the solve error far below the
    /// step's own O(h) error at 1 ms (see bench/ speed-versus-error).
    double m_tolerance = 1e-6;
    int m_maxIterations = 500;
    int m_lastIterations = 0;
    double m_lastResidual = 0.0;
    Forces m_f;
    Eigen::Matrix3Xd m_rhs, m_dv, m_r, m_z, m_p, m_ap, m_kTmp, m_dTmp;
    Eigen::VectorXd m_precond, m_kRow, m_cRow;
    std::vector<std::uint8_t> m_mask;
    std::vector<ForceTerm*> m_frozen;    ///< terms that add h D + h^2 K+ in one pass
    std::vector<ForceTerm*> m_unfrozen;  ///< symmetric terms multiplied by K+ and D separately
};

}  // namespace colonosim::physics
