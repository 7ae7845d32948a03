#pragma once
/// \file
/// The discrete rod of the colonoscope (de Visser et al. 2010, seed 001
/// section 2.5): n nodes joined by n - 1 rigid elements of equal length l,
/// inextensible and shear-free. Each element k carries a material frame C_k
/// whose columns are (right, up, forward), forward being the element's
/// direction. The deformation is concentrated in joints: joint k sits at node
/// k and rotates the frame by Theta_k (two bending increments about right and
/// up, one torsion about forward) relative to the frame before it:
///
///     C_k = C_{k-1} D_k R(Theta_k),   x_{k+1} = x_k + l C_k e_3   (eqs 6-7)
///
/// with C_{-1} the clamp frame at the base and D_k the rest rotation set by
/// the control dials (identity outside the bending section; the dial angles
/// are superimposed on the computed deflection, section 2.5). The internal
/// moment of joint k is K_k Theta_k with K = diag(EI, EI, GJ)/l (eq 2).
///
/// Joint 0 (at the clamp) represents the clamped stub and half an element,
/// stiffness K l / (stub + l/2) (2K when the stub is empty); joint n - 1 (at
/// the tip) represents half an element, 2K. As the stub grows to l and the
/// next node passes the clamp, the compliance between the clamp and the old
/// node 0 (1.5 l / EI) is the same before and after: the rod does not jump
/// as it is inserted. Interior joints represent the element
/// length around their node (a midpoint rule: positions converge as 1/n^2,
/// and a uniform end moment gives the exact tip angle ML/EI). The tip joint
/// rotates only the tip frame C_{n-1} (the camera frame), not an element.
/// The base node x_0 lies a straight clamped stub of length `stubLength`
/// beyond the clamp point (partial insertion, see Colonoscope.h).
///
/// External loads are a force and a torque per node (world frame, dead
/// loads). A torque at an interior node k acts on element k - 1; the torque
/// at the tip acts on the tip frame; loads at node 0 go straight to the clamp.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace colonosim::scope {

/// Storage in structure-of-arrays form; vectors are sized once (capacity),
/// and resizing within the capacity does not allocate.
struct DiscreteRod {
    double elementLength = 0.0;                               ///< l, m
    Eigen::Vector3d stiffness = Eigen::Vector3d::Zero();      ///< diag(EI, EI, GJ)/l, N m/rad
    Eigen::Vector3d basePosition = Eigen::Vector3d::Zero();   ///< clamp point, m
    Eigen::Matrix3d baseFrame = Eigen::Matrix3d::Identity();  ///< C_{-1}, columns right, up, forward
    double stubLength = 0.0;                                  ///< clamped straight stub to node 0, m

    std::vector<Eigen::Vector3d> theta;     ///< Theta_k, joints 0..n-1, rad
    std::vector<Eigen::Matrix3d> dial;      ///< D_k, rest rotation from the dials
    std::vector<unsigned char> hasDial;     ///< 1 where D_k is not the identity
    std::vector<Eigen::Vector3d> force;     ///< per node, N
    std::vector<Eigen::Vector3d> torque;    ///< per node, N m
    std::vector<Eigen::Vector3d> position;  ///< x_k, m (derived)
    std::vector<Eigen::Matrix3d> frame;     ///< C_k; C_{n-1} is the tip frame (derived)
    /// Rodrigues' coefficients (a, b) of R(Theta_k) (derived; see Rotation.h).
    std::vector<Eigen::Array2d> rodrigues;
    std::vector<Eigen::Matrix3d> rotation;  ///< D_k R(Theta_k) (derived)
    /// D_k, the step's damping of joint k, N m/rad (0: quasi-static); the
    /// chain solves K Theta + D (Theta - thetaStart) = C^T M.
    std::vector<Eigen::Vector3d> damping;
    std::vector<Eigen::Vector3d> thetaStart;  ///< Theta at the start of the step, rad
    /// w / (K_k + D_k) of the chain's relaxation, rad/(N m) (derived, set by solveChain).
    std::vector<Eigen::Vector3d> relaxationGain;
    /// D_k Theta_start,k, N m (derived, set by solveChain).
    std::vector<Eigen::Vector3d> dampingPull;

    /// A straight rod of `numNodes` nodes (capacity `capacity` >= numNodes).
    void reset(int numNodes, double length, double flexuralRigidity, double torsionalRigidity, int capacity);
    [[nodiscard]] int numNodes() const { return static_cast<int>(theta.size()); }
    /// K_k: see above for the clamp and tip joints.
    [[nodiscard]] Eigen::Vector3d jointStiffness(int joint) const;
    /// K_k + D_k: how joint k resists a load within one step.
    [[nodiscard]] Eigen::Vector3d jointResistance(int joint) const
    {
        return jointStiffness(joint) + damping[static_cast<size_t>(joint)];
    }
    /// Frame before joint k: C_{k-1}, or the clamp frame for k = 0.
    [[nodiscard]] const Eigen::Matrix3d& frameBefore(int joint) const;
    /// Changes the node count keeping the tip end: joints are added (straight)
    /// or dropped at the base, so the deformation of each material joint is
    /// carried over. Loads are cleared.
    void resizeAtBase(int numNodes);
    /// Eqs 6-7: positions and frames from the base to the tip (and the
    /// rotations D_k R(Theta_k) they are built from).
    void rebuild();
    void clearLoads();
};

}  // namespace colonosim::scope
