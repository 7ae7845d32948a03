// The scope's side of contact: the Delassus matrix of the clamped rod against
// the chain solver's own response, the one-step Newton update, the trust
// region, release, and the wall's view of a contact.

#include "simcore/procedure/ContactCoupling.h"
#include "simcore/scope/Colonoscope.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using colonosim::contact::ContactResult;
using colonosim::contact::ScopeContact;
using colonosim::procedure::ContactCoupling;
using colonosim::scope::Colonoscope;

constexpr double kStiffness = 1e4;  // N/m, the declared contact stiffness
constexpr double kRadius = 0.0065;  // m

Colonoscope straightScope(double insertion)
{
    Colonoscope scope;
    scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    scope.setInsertion(insertion);
    return scope;
}

/// A penalty contact on node `node` (as the end of segment node - 1) pushing along +y.
ScopeContact contactAt(int node, double depth)
{
    ScopeContact c;
    c.segment = node - 1;
    c.segmentParam = 1.0;
    c.triangle = 0;
    c.depth = depth;
    c.normal = Eigen::Vector3d::UnitY();
    c.normalForce = kStiffness * depth;
    return c;
}

/// A wall triangle under `node`, facing +y, one radius below the axis.
colonosim::geometry::TriangleMesh floorUnder(const Eigen::Vector3d& node, Eigen::Matrix3Xd& wall)
{
    colonosim::geometry::TriangleMesh mesh;
    mesh.vertices.resize(3, 3);
    mesh.vertices.col(0) = node + Eigen::Vector3d(-0.01, -kRadius, -0.01);
    mesh.vertices.col(1) = node + Eigen::Vector3d(0.0, -kRadius, 0.02);
    mesh.vertices.col(2) = node + Eigen::Vector3d(0.01, -kRadius, -0.01);
    mesh.triangles.push_back({0, 1, 2});
    wall = mesh.vertices;
    return mesh;
}

double solvedDeflection(Colonoscope& scope, int node, const Eigen::Vector3d& force, int measured)
{
    const Eigen::Vector3d before = scope.nodePositions()[static_cast<size_t>(measured)];
    scope.clearLoads();
    scope.setNodeForce(node, force);
    for (int s = 0; s < 40; ++s) {
        scope.step();
    }
    const double moved = (scope.nodePositions()[static_cast<size_t>(measured)] - before).y();
    scope.clearLoads();
    for (int s = 0; s < 40; ++s) {
        scope.step();
    }
    return moved;
}

// G_ab is the rod's compliance: a force along n_b at node b moves node a by
// G_ab along n_a. Checked against the chain solver's converged response for
// small loads (linear range), diagonal and off-diagonal.
TEST(ContactCoupling, DelassusMatrixIsTheRodsOwnCompliance)
{
    Colonoscope scope = straightScope(0.2);
    const int tip = scope.numInsertedNodes() - 1;
    const int mid = tip / 2;
    Eigen::Matrix3Xd wall;
    const auto mesh = floorUnder(scope.nodePositions().back(), wall);
    ContactResult raw;
    raw.contacts = {contactAt(mid, 1e-6), contactAt(tip, 1e-6)};
    ContactCoupling coupling(kStiffness, 1.0);
    coupling.update(raw, scope.rod(), 0, mesh, wall, kRadius);
    ASSERT_EQ(coupling.activeNodes().size(), 2U);
    const Eigen::MatrixXd& g = coupling.delassus();
    const double f = 1e-4;  // N
    const double gTipTip = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, f, 0.0), tip) / f;
    const double gMidTip = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, f, 0.0), mid) / f;
    const double gMidMid = solvedDeflection(scope, mid, Eigen::Vector3d(0.0, f, 0.0), mid) / f;
    EXPECT_NEAR(g(1, 1), gTipTip, 1e-3 * gTipTip);
    EXPECT_NEAR(g(0, 1), gMidTip, 1e-3 * gTipTip);
    EXPECT_NEAR(g(0, 0), gMidMid, 1e-3 * gMidMid);
    // Cantilever closed form for the tip: L^3 / 3 EI (discrete rod, 1%).
    const double ei = colonosim::scope::ScopeParameters{}.flexuralRigidity;
    EXPECT_NEAR(g(1, 1), std::pow(0.2, 3) / (3.0 * ei), 0.01 * g(1, 1));
}

// For one contact the Newton step is exact: lambda = k_c d0 / (1 + k_c G),
// and once the rod carries it, the remaining depth gives back lambda = k_c d.
TEST(ContactCoupling, OneContactIsResolvedInOneStep)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::Matrix3Xd wall;
    const auto mesh = floorUnder(scope.nodePositions().back(), wall);
    const double depth = 2e-3;  // m
    ContactResult raw;
    raw.contacts = {contactAt(tip, depth)};
    ContactCoupling coupling(kStiffness, 1.0);
    coupling.update(raw, scope.rod(), 0, mesh, wall, kRadius);
    const double g = coupling.delassus()(0, 0);
    const double lambda = coupling.loads().col(tip).y();
    EXPECT_NEAR(lambda, kStiffness * depth / (1.0 + kStiffness * g), 1e-9);
    for (int i = 0; i < tip; ++i) {
        EXPECT_EQ(coupling.loads().col(i).norm(), 0.0);
    }
    // The rod under lambda rises by G lambda (so the depth left, d - G lambda,
    // has the penalty force lambda: equilibrium in one step).
    const double rise = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, lambda, 0.0), tip);
    EXPECT_NEAR(rise, g * lambda, 1e-3 * rise);
    EXPECT_GT(rise, 0.99 * depth) << "a 15 cm tip is far softer than the penalty: it gives way";
}

// A contact-driven step never moves a node by more than the trust region.
TEST(ContactCoupling, TheTrustRegionBoundsTheMotionOfOneStep)
{
    Colonoscope scope = straightScope(0.3);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::Matrix3Xd wall;
    const auto mesh = floorUnder(scope.nodePositions().back(), wall);
    ContactResult raw;
    raw.contacts = {contactAt(tip, 0.02)};
    const double maxStep = 1e-4;
    ContactCoupling coupling(kStiffness, maxStep);
    coupling.update(raw, scope.rod(), 0, mesh, wall, kRadius);
    const double g = coupling.delassus()(0, 0);
    const double lambda = coupling.loads().col(tip).y();
    EXPECT_GT(lambda, 0.0);
    EXPECT_NEAR(g * lambda, maxStep, 1e-12);
}

// A node that carried a load and is now clear of its wall lets go at once;
// no load pulls, and a node that never touched carries nothing.
TEST(ContactCoupling, ReleaseIsImmediateAndContactNeverPulls)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::Matrix3Xd wall;
    const auto mesh = floorUnder(scope.nodePositions().back(), wall);
    ContactResult raw;
    raw.contacts = {contactAt(tip, 1e-3)};
    ContactCoupling coupling(kStiffness, 1.0);
    coupling.update(raw, scope.rod(), 0, mesh, wall, kRadius);
    ASSERT_GT(coupling.loads().col(tip).y(), 0.0);
    // The wall drops 5 mm away: no contact found this step.
    wall.row(1).array() -= 0.005;
    coupling.update(ContactResult{}, scope.rod(), 0, mesh, wall, kRadius);
    EXPECT_EQ(coupling.loads().col(tip).norm(), 0.0);
    EXPECT_TRUE(coupling.activeNodes().empty() ||
                coupling.normalLoads()[static_cast<size_t>(tip)].norm() == 0.0);
}

// The wall meets the scope through its compliance: k_eff = k_c / (1 + k_c G)
// and the depth offset is the scope's deflection under its current load.
TEST(ContactCoupling, TheWallSeesTheSeriesStiffness)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::Matrix3Xd wall;
    const auto mesh = floorUnder(scope.nodePositions().back(), wall);
    ContactResult raw;
    raw.contacts = {contactAt(tip, 1e-3)};
    ContactCoupling coupling(kStiffness, 1.0);
    coupling.update(raw, scope.rod(), 0, mesh, wall, kRadius);
    const double g = coupling.delassus()(0, 0);
    const double lambda = coupling.loads().col(tip).y();
    ASSERT_EQ(coupling.wallPoints().size(), 1U);
    const auto& p = coupling.wallPoints()[0];
    EXPECT_NEAR(p.stiffness, kStiffness / (1.0 + kStiffness * g), 1e-9);
    EXPECT_NEAR(p.depthOffset, g * lambda, 1e-15);
    EXPECT_LE(p.stiffness, kStiffness);
}

}  // namespace
