#pragma once
/// \file
/// The colonoscope: the discrete rod (DiscreteRod.h) solved by the chain
/// solver (ChainSolver.h), driven at the anus by the handle, with the tip
/// bending section steered by the dials. de Visser et al. 2010, seed 001
/// sections 2.5 and 2.7.
///
/// Handle and insertion. The anus is a clamp with a pose (position,
/// insertion direction, reference up) set by the caller. The scope's nodes
/// sit at fixed material points l = workingLength / (numNodes - 1) apart,
/// counted from the tip; the inserted length s decides which are inside:
/// n = floor(s / l) + 1 nodes, the base node lying a straight clamped stub
/// of length s - (n - 1) l beyond the anus. As s grows the stub lengthens
/// until the next node passes the anus and joins the chain straight; each
/// material joint keeps its deformation (the warm start carries over).
/// Shaft rotation at the handle turns the clamp frame about the insertion
/// direction; it reaches the tip only through the modelled torsion, resisted
/// by tip contact torques.
///
/// Dials. Up/down and left/right angles are clamped to the declared clinical
/// limits and spread evenly over the joints of the bending section (the
/// round(bendingSectionLength / l) interior joints nearest the tip) as rest
/// rotations, superimposed on the computed deflection. Up bends towards the
/// tip frame's up column, right towards its right column. While the bending
/// section is entering, the joint at the clamp takes the inserted fraction
/// of its share, so the tip does not jump when a node passes the anus.
///
/// Outputs: node positions (base to tip), the tip pose (camera frame:
/// columns right, up, forward) and the handle load: eq 1 at the clamp, the
/// sum of the environmental loads on the inserted scope and their moment
/// about the anus, with the axial force (along the insertion direction) and
/// the axial torque (about it) for a haptic device (25 N, 1 N m, section 2.7).

#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/DiscreteRod.h"
#include "simcore/scope/ScopeParameters.h"

#include <Eigen/Core>

#include <functional>
#include <span>
#include <vector>

namespace colonosim::scope {

struct TipPose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
    /// Columns x, y, z of a right-handed frame: z forward (the viewing
    /// direction), y up, and x = y cross z, which is the viewer's LEFT (the
    /// image's right is z cross y = -x). The rod names x "right" as its
    /// bending axis; a positive left/right dial turns the tip towards +x.
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

struct HandleLoad {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< sum of loads on the scope, world, N
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< about the anus, world, N m
    double axialForce = 0.0;  ///< force . insertion direction, N (negative resists insertion)
    /// Moment about the shaft, counter-clockwise seen from the operator
    /// (-moment . insertion direction, the convention of setShaftRotation()), N m.
    double axialTorque = 0.0;
};

class Colonoscope {
public:
    /// Validates the parameters (ParameterError); starts straight, not inserted.
    explicit Colonoscope(const ScopeParameters& parameters = {});

    /// Anus position and insertion direction (non-zero); `up` must not be
    /// parallel to it. Refuses non-finite input.
    void setHandlePose(const Eigen::Vector3d& anus, const Eigen::Vector3d& direction,
                       const Eigen::Vector3d& up);
    /// Inserted length in [0, workingLength], m.
    void setInsertion(double length);
    /// Shaft rotation at the handle, rad, |angle| <= 1000: counter-clockwise
    /// seen from the operator looking along the insertion direction (a
    /// rotation about the backward axis).
    void setShaftRotation(double angle);
    /// Dial angles, rad; clamped to the clinical limits; non-finite or beyond 2 pi refused.
    void setDials(double upDown, double leftRight);

    [[nodiscard]] int numInsertedNodes() const { return m_rod.numNodes(); }
    void clearLoads() { m_rod.clearLoads(); }
    /// Environmental load on inserted node `node` (0 = base, numInsertedNodes() - 1 = tip).
    void setNodeForce(int node, const Eigen::Vector3d& force);
    void setNodeTorque(int node, const Eigen::Vector3d& torque);
    /// Adds the weight of the inserted scope (linear mass density x inserted length x g)
    /// to the node forces, lumped per node.
    void addGravity(const Eigen::Vector3d& gravity);

    /// Starts a time step of `dt` s: each joint is damped by the inertia of
    /// the scope downstream of it, I_k = sum_{j > k} m_j |x_j - x_k|^2, at
    /// damping ratio zeta: D_k = 2 zeta sqrt(K_k I_k) / dt.
    void beginStep(double dt, double dampingRatio);
    /// One time step: `solverIterations` chain iterations, warm-started.
    /// Guarded after a damped beginStep(): when the solve leaves a node more
    /// than `maxNodeStep` from where the step began, the joints are put back
    /// where this call found them, their damping is raised fourfold, and the
    /// chain is solved again, at most three times (the last solve is kept).
    /// A rod loaded beyond what the damped chain iteration can follow (a
    /// shaft pressed near its buckling load) otherwise diverges in one step.
    void step();
    /// The same iterations, calling `afterIteration` on the rod after each
    /// (loads that depend on the shape, such as contact, are updated there);
    /// not guarded: its caller changes the loads between iterations.
    void step(const std::function<void(DiscreteRod&)>& afterIteration);

    /// Solves the step guard refused since the last beginStep().
    [[nodiscard]] int guardRetries() const { return m_guardRetries; }

    [[nodiscard]] std::span<const Eigen::Vector3d> nodePositions() const { return m_rod.position; }
    [[nodiscard]] TipPose tipPose() const;
    [[nodiscard]] HandleLoad handleLoad() const;
    [[nodiscard]] double upDownDial() const { return m_upDown; }
    [[nodiscard]] double leftRightDial() const { return m_leftRight; }
    [[nodiscard]] const ScopeParameters& parameters() const { return m_parameters; }
    [[nodiscard]] const DiscreteRod& rod() const { return m_rod; }
    /// Mutable access for the reference solver and tests.
    [[nodiscard]] DiscreteRod& rod() { return m_rod; }

private:
    void updateBase();
    void updateDials();
    /// The largest distance of a node from its place at beginStep(), m.
    [[nodiscard]] double largestStepMotion() const;

    ScopeParameters m_parameters;
    DiscreteRod m_rod;
    double m_materialElementLength = 0.0;
    Eigen::Vector3d m_anus = Eigen::Vector3d::Zero();
    Eigen::Matrix3d m_entryFrame = Eigen::Matrix3d::Identity();
    double m_insertion = 0.0;
    double m_shaftRotation = 0.0;
    double m_upDown = 0.0;
    double m_leftRight = 0.0;
    // The step guard: node positions at beginStep() (empty: no guard), the
    // joints as step() found them, and the solves refused this step.
    std::vector<Eigen::Vector3d> m_stepStart;
    std::vector<Eigen::Vector3d> m_thetaBefore;
    int m_guardRetries = 0;
};

}  // namespace colonosim::scope
