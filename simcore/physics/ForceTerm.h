#pragma once
/// \file
/// The one interface every tissue force shares (after Bullet's
/// btDeformableLagrangianForce): add the elastic force, add the damping
/// force, add the force differentials for the implicit solve, and report the
/// Gershgorin row sums that bound the highest natural frequency.
///
/// Sign convention: K = df/dx and D = df/dv (both negative semi-definite for
/// springs). For the stable explicit step, omega_max^2 <= max_i kRow_i / m_i
/// (Gershgorin on M^-1 K), where kRow_i sums the norms of the 3x3 blocks of
/// row i of K, diagonal and off-diagonal (reference/physical-parameters.md).

#include <Eigen/Core>

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

namespace colonosim::physics {

using Positions = Eigen::Matrix3Xd;   ///< one column per node, m
using Velocities = Eigen::Matrix3Xd;  ///< m/s
using Forces = Eigen::Matrix3Xd;      ///< N

class ForceTerm {
public:
    virtual ~ForceTerm() = default;

    [[nodiscard]] virtual std::string_view name() const = 0;

    /// f += elastic (and external) force at positions x.
    virtual void addForce(const Positions& x, Forces& f) const = 0;
    /// f += damping force at (x, v).
    virtual void addDampingForce(const Positions& x, const Velocities& v, Forces& f) const = 0;
    /// f += elastic + damping force. Terms override it to do one pass.
    virtual void addForceAndDamping(const Positions& x, const Velocities& v, Forces& f) const
    {
        addForce(x, f);
        addDampingForce(x, v, f);
    }
    /// df += K(x) dx with K = d(elastic force)/dx.
    virtual void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                     Eigen::Matrix3Xd& df) const = 0;
    /// df += K+(x) dx, a negative semi-definite version of K for the implicit
    /// solve (e.g. compressed springs lose their transverse term, Choi & Ko
    /// 2002). Defaults to the exact product.
    virtual void addDefiniteStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                             Eigen::Matrix3Xd& df) const
    {
        addStiffnessProduct(x, dx, df);
    }
    /// df += D(x) dv with D = d(damping force)/dv.
    virtual void addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv,
                                   Eigen::Matrix3Xd& df) const = 0;
    /// Freezes the implicit solve's linear system at x for a step of h:
    /// returns true if the term then adds (h D + h^2 K+) y in
    /// addSystemProduct, from what it kept of x (each conjugate-gradient
    /// iteration multiplies by it at the same x). False by default: the solver
    /// multiplies by K+ and D separately.
    virtual bool linearize(const Positions& x, double h)
    {
        (void)x;
        (void)h;
        return false;
    }
    /// out += (h D + h^2 K+) y at the x and h of the last linearize() that
    /// returned true (the sign convention above: both products negative
    /// semi-definite).
    virtual void addSystemProduct(const Eigen::Matrix3Xd& y, Eigen::Matrix3Xd& out) const
    {
        (void)y;
        (void)out;
    }
    /// kRow(i) += sum over j of ||K_ij|| at state x, or at the worst state
    /// the term declares where that is tighter to state (a stiffening
    /// mesentery at its declared maximum stretch); cRow(i) likewise for D.
    virtual void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow,
                                   Eigen::VectorXd& cRow) const = 0;
    /// Appends the pairs of distinct nodes whose stiffness block K_ij this
    /// term can make non-zero (the static solver's preconditioner assembles
    /// K over them; see TangentPreconditioner.h). None by default: a term
    /// acting on each node alone.
    virtual void addCouplings(std::vector<std::pair<int, int>>& pairs) const { (void)pairs; }
    /// False for a term whose couplings come and go with the state and are
    /// not listed by addCouplings (contact): probing it would mix the columns
    /// of the nodes that share a colour, so the preconditioner leaves it out
    /// (TissueBody::declaredStiffnessProduct) and the conjugate gradients,
    /// which multiply by every term, take a few more iterations for it.
    [[nodiscard]] virtual bool couplingsDeclared() const { return true; }
    /// Potential energy of the elastic part, J (0 for non-conservative terms).
    [[nodiscard]] virtual double potentialEnergy(const Positions& x) const = 0;
    /// True when K and D are symmetric, so the implicit solver may include
    /// them in its conjugate-gradient system; other terms are treated
    /// explicitly there.
    [[nodiscard]] virtual bool hasSymmetricJacobian() const { return true; }
    /// The set of awake nodes changed: terms may skip elements whose nodes
    /// all sleep. `awake` has one entry per node.
    virtual void onActiveSetChanged(const std::vector<std::uint8_t>& awake) { (void)awake; }
    /// Node masses changed or nodes were appended (kg, one per node). Terms
    /// that scale with mass (gravity, drag) keep their copy in step.
    virtual void onMassesChanged(const Eigen::VectorXd& masses) { (void)masses; }
};

}  // namespace colonosim::physics
