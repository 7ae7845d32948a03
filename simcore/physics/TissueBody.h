#pragma once
/// \file
/// A deformable body of point masses: state (positions, velocities) in
/// structure-of-arrays Eigen storage, masses, fixed nodes, external loads,
/// force terms and constraints, and the awake/asleep set of the active region.
///
/// Equations of motion: M dv/dt = f(x, v) + f_ext, dx/dt = v, with fixed
/// nodes held (their rows are zero). No damping is added here: every damping
/// force is a declared force term.
///
/// Topology stays editable: nodes can be appended and force terms hold flat
/// element arrays that support local insertion and removal.

#include "simcore/physics/Constraint.h"
#include "simcore/physics/ForceTerm.h"

#include <memory>
#include <vector>

namespace colonosim::physics {

class TissueBody {
public:
    TissueBody() = default;
    TissueBody(const Positions& restPositions, const Eigen::VectorXd& masses);

    [[nodiscard]] int numNodes() const { return static_cast<int>(m_x.cols()); }

    Positions& positions() { return m_x; }
    [[nodiscard]] const Positions& positions() const { return m_x; }
    Velocities& velocities() { return m_v; }
    [[nodiscard]] const Velocities& velocities() const { return m_v; }
    [[nodiscard]] const Eigen::VectorXd& masses() const { return m_mass; }
    [[nodiscard]] const Eigen::VectorXd& inverseMasses() const { return m_inverseMass; }

    /// Appends a node (kg, m); returns its index.
    int addNode(const Eigen::Vector3d& position, double mass);
    void setMass(int node, double mass);
    void setFixed(int node, bool fixed);
    [[nodiscard]] bool isFixed(int node) const { return m_fixed[static_cast<size_t>(node)] != 0; }

    /// Loads from outside the body (contact, instruments), N. Applying one
    /// wakes the node. Cleared by clearExternalForces().
    void applyExternalForce(int node, const Eigen::Vector3d& force);
    void clearExternalForces();
    /// Marks a node as loaded this step (by a force term such as contact):
    /// it wakes now and the active region keeps it awake until the loads are
    /// cleared. applyExternalForce() does the same.
    void holdAwake(int node);
    [[nodiscard]] bool isHeldAwake(int node) const { return m_held[static_cast<size_t>(node)] != 0; }
    [[nodiscard]] const Forces& externalForces() const { return m_external; }

    ForceTerm& addForceTerm(std::unique_ptr<ForceTerm> term);
    void addConstraint(std::unique_ptr<Constraint> constraint);
    [[nodiscard]] const std::vector<std::unique_ptr<ForceTerm>>& forceTerms() const { return m_terms; }

    /// f = sum of all force terms (elastic + damping) + external loads; zero on fixed nodes.
    void computeForces(const Positions& x, const Velocities& v, Forces& f) const;
    /// The same sums at the integrated nodes, for an integrator that reads
    /// no other column: f (sized for every node) gets the external forces
    /// only at the integrated nodes before the terms add theirs, so the
    /// columns it reads are those of computeForces() bit for bit and the
    /// sleeping nodes' columns (which the terms may add to) are not reset.
    void computeIntegratedForces(const Positions& x, const Velocities& v, Forces& f) const;
    /// df = K dx (+ damping D dv when dv given) summed over terms with a
    /// symmetric Jacobian; zero rows on fixed nodes.
    void stiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df,
                          bool definite = false) const;
    /// df = K+ dx summed over the terms whose couplings are declared
    /// (ForceTerm::couplingsDeclared): what the static solver's
    /// preconditioner probes.
    void declaredStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df) const;
    void dampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df) const;
    /// Applies every constraint to the integrated nodes.
    int projectConstraints(Positions& x, Velocities& v) const;

    [[nodiscard]] double kineticEnergy() const;
    [[nodiscard]] double potentialEnergy() const;

    /// Nodes the integrators advance: not fixed and awake.
    [[nodiscard]] const std::vector<int>& integratedNodes() const { return m_integrated; }
    [[nodiscard]] const std::vector<std::uint8_t>& awake() const { return m_awake; }
    /// Sets the awake flags (one per node) and rebuilds the active lists.
    void setAwake(const std::vector<std::uint8_t>& awake);

    /// Gershgorin row sums of K and D over all terms, one entry per node.
    void stiffnessBounds(Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const;

private:
    void rebuildIntegratedNodes();
    /// After m_awake changed: resting velocities, lists, terms.
    void applyAwake();

    Positions m_x;
    Velocities m_v;
    Eigen::VectorXd m_mass;
    Eigen::VectorXd m_inverseMass;
    std::vector<std::uint8_t> m_fixed;
    std::vector<std::uint8_t> m_awake;
    std::vector<std::uint8_t> m_held;  ///< loaded this step
    std::vector<int> m_integrated;
    Forces m_external;
    std::vector<std::unique_ptr<ForceTerm>> m_terms;
    std::vector<std::unique_ptr<Constraint>> m_constraints;
};

}  // namespace colonosim::physics
