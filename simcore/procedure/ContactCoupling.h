#pragma once
/// \file
/// The scope's side of scope-wall contact: the contact load on each scope
/// node for the next chain solve, from this step's penalty contacts.
///
/// Why not apply the penalty forces directly. The scope is quasi-static (the
/// chain solver finds its equilibrium under the loads of the step) and the
/// penalty is stiff: k_c = 1e4 N/m against a lateral tip stiffness of
/// 3 EI / L^3 = 160 N/m at 8 cm of insertion and 12 N/m at 20 cm. Applying
/// k_c d as a load, re-solving, re-measuring d and so on is a fixed-point
/// iteration with gain k_c C (C the rod's compliance at the contact), far
/// above 1: the tip bounces from wall to wall. A fixed under-relaxation only
/// moves the limit (0.02 diverges beyond about 10 cm).
///
/// What is done instead: one Newton step per loop step on the contact normal
/// forces lambda (one per scope node in contact, along that node's contact
/// normal n_a), with the rod's own compliance. A load change delta moves node
/// a by (G delta)_a along n_a, where G is the Delassus matrix of the clamped
/// rod, G_ab = n_a^T C_ab n_b,
///     C_ab = sum_{k < min(a,b)} [r_ak]x^T C_k K_k^-1 C_k^T [r_bk]x,
/// r_ak = x_a - x_k (a rotation of joint k moves node a by w x r_ak), built in
/// O(n + m^2) from prefix sums over the joints. With r = k_c d measured on the
/// current shape (which already carries the last loads),
///     (I + k_c G) delta = r - lambda_old,   lambda = max(0, lambda_old + delta),
/// exact in one step for fixed contacts and a converged rod (nodes that would
/// pull are fixed at zero and the rest re-solved). A trust region then limits
/// the contact-driven motion of each node in one step to maxStep along its
/// normal (G_aa |delta_a| <= maxStep): contacts appear and vanish as the tip
/// swings across a lumen, and without it the exact step ping-pongs between
/// opposite walls.
///
/// Release: a node that carried a load but finds no contact this step keeps
/// its last normal and triangle, and its signed gap to that triangle's plane
/// gives r = k_c min(0, depth): lambda goes to zero at once when the wall has
/// moved away (no phantom load). Friction follows the normal force: the raw
/// friction of the node scaled by lambda / r, so it stays inside the cone.
///
/// The wall side (WallContactForce, over the tissue substeps) meets the
/// scope through the same compliance: contact c at parameter t of segment
/// (s, s+1) has G_c = (1-t) G_ss + t G_{s+1,s+1}, stiffness k_c / (1 + k_c G_c)
/// and depth offset (1-t) (G lambda)_s + t (G lambda)_{s+1} (the scope's
/// deflection under its current loads), so at the start of the substeps the
/// wall receives what the scope receives, and as the wall gives way the force
/// falls with the series stiffness of scope and penalty instead of bouncing
/// off k_c.

#include "simcore/contact/ScopeWallContact.h"
#include "simcore/contact/WallContactForce.h"
#include "simcore/geometry/TriangleMesh.h"
#include "simcore/scope/DiscreteRod.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::procedure {

class ContactCoupling {
public:
    /// `contactStiffness` k_c, N/m; `maxStep` the trust region, m per loop step.
    ContactCoupling(double contactStiffness, double maxStep)
        : m_stiffness(contactStiffness), m_maxStep(maxStep)
    {}

    /// Updates the node loads from `raw` (the penalty contacts of the
    /// current scope shape, which carries the loads of the previous update).
    /// `addedAtBase` nodes entered the rod at the base since the last call
    /// (negative when nodes left); `wall` are the wall positions.
    void update(const contact::ContactResult& raw, const scope::DiscreteRod& rod, int addedAtBase,
                const geometry::TriangleMesh& mesh, const Eigen::Matrix3Xd& wall, double radius);

    /// Contact load on each inserted node (base to tip), N.
    [[nodiscard]] const Eigen::Matrix3Xd& loads() const { return m_loads; }
    /// How the wall sees each contact of `raw` (same order) over the tissue
    /// substeps: the scope point, k_eff = k_c / (1 + k_c G) and the depth
    /// offset (G lambda), so the wall meets the scope through its compliance.
    [[nodiscard]] const std::vector<contact::WallContactPoint>& wallPoints() const { return m_wallPoints; }
    /// Normal load carried by each node, N (world).
    [[nodiscard]] const std::vector<Eigen::Vector3d>& normalLoads() const { return m_load; }
    /// The nodes in this step's update and their Delassus matrix G, m/N.
    [[nodiscard]] const std::vector<int>& activeNodes() const { return m_active; }
    [[nodiscard]] Eigen::MatrixXd delassus() const
    {
        const auto m = static_cast<Eigen::Index>(m_active.size());
        return m_delassus.topLeftCorner(m, m);
    }

private:
    void align(int numNodes, int addedAtBase);
    void reserve(int numNodes);
    void buildCompliance(const scope::DiscreteRod& rod);
    void solveNormalForces();

    double m_stiffness;
    double m_maxStep;
    std::vector<Eigen::Vector3d> m_load;    ///< lambda_a, N, per node
    std::vector<Eigen::Vector3d> m_normal;  ///< normal of the strongest contact, per node
    std::vector<int> m_triangle;            ///< last contact triangle per node (-1: none)
    std::vector<int> m_active;              ///< nodes in the update
    // Working storage sized once to the longest inserted scope (reserve());
    // only the leading m = m_active.size() entries are in use each step.
    Eigen::MatrixXd m_delassus;  ///< G over m_active, m/N
    Eigen::VectorXd m_raw;       ///< k_c d along n_a over m_active (signed), N
    Eigen::VectorXd m_previous;  ///< lambda of the last step along n_a, N
    Eigen::VectorXd m_lambda;    ///< this step's normal forces, N
    Eigen::MatrixXd m_system;    ///< I + k_c G over the free nodes
    Eigen::VectorXd m_fixedDelta, m_coupling, m_rhs;
    std::vector<char> m_free;
    std::vector<Eigen::Index> m_freeIndex;
    std::vector<Eigen::Vector3d> m_rawNormal, m_rawFriction;  ///< per node, N
    std::vector<double> m_strongest;                          ///< per node, N
    std::vector<double> m_compliance;                         ///< G_aa per node, m/N
    std::vector<double> m_deflection;                         ///< (G lambda)_a per node, m
    std::vector<contact::WallContactPoint> m_wallPoints;
    Eigen::Matrix3Xd m_loads;
    // Prefix sums over the joints (A = sum W, B = sum W X, C = sum X^T W X).
    std::vector<Eigen::Matrix3d> m_prefixA, m_prefixB, m_prefixC;
};

}  // namespace colonosim::procedure
