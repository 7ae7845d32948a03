// The scope-wall contact law in a rigid straight tube (radius 20 mm, wall
// nodes fixed): momentum balance, friction cone, stick and slip, and no
// tunnelling of kinematically and penalty-driven chains at insertion speeds.

#include "simcore/contact/ScopeWallContact.h"
#include "simcore/physics/SpringCalibration.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace colonosim::contact {
namespace {

constexpr double kRadius = 6.5e-3;  ///< scope radius, m
constexpr double kDt = 1e-3;        ///< loop step, s

geometry::TriangleMesh tube()
{
    return physics::makeStraightTube(physics::TubeResolution{});  // radius 20 mm, 0.41 m long
}

/// Towards the middle of a wall face (between the nodes at 0 and 22.5 degrees).
Eigen::Vector3d faceDirection()
{
    const double a = std::numbers::pi / 16.0;
    return {std::cos(a), std::sin(a), 0.0};
}

/// A chain of `n` nodes 10 mm apart along z from z0, offset by `offset` across the tube.
Eigen::Matrix3Xd chain(int n, double z0, const Eigen::Vector3d& offset)
{
    Eigen::Matrix3Xd x(3, n);
    for (int i = 0; i < n; ++i) {
        x.col(i) = offset + Eigen::Vector3d(0.0, 0.0, z0 + 0.01 * i);
    }
    return x;
}

/// The smallest signed distance, along the inward normals, of `p` to the
/// planes of the wall faces spanning its z: negative when outside the tube.
double insideMargin(const geometry::TriangleMesh& mesh, const Eigen::Vector3d& p)
{
    double margin = 1.0;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = mesh.vertices.col(t[0]);
        const Eigen::Vector3d b = mesh.vertices.col(t[1]);
        const Eigen::Vector3d c = mesh.vertices.col(t[2]);
        const double zMin = std::min({a.z(), b.z(), c.z()});
        const double zMax = std::max({a.z(), b.z(), c.z()});
        if (p.z() >= zMin && p.z() <= zMax) {
            margin = std::min(margin, -(p - a).dot((b - a).cross(c - a).normalized()));
        }
    }
    return margin;
}

TEST(ScopeWallContact, RefusesInvalidParameters)
{
    ContactParameters p;
    p.frictionCoefficient = -0.1;
    EXPECT_THROW(ScopeWallContact(tube(), p), params::ParameterError);
}

TEST(ScopeWallContact, ForcesBalanceAndStayInTheFrictionCone)
{
    const geometry::TriangleMesh mesh = tube();
    ScopeWallContact contact(mesh);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    Eigen::Matrix3Xd wallV(3, mesh.numVertices());
    for (int i = 0; i < wallV.cols(); ++i) {
        wallV.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    // Offset 16 mm towards a face: the capsule surface reaches 22.5 mm, past the 19.6 mm face.
    const Eigen::Matrix3Xd x = chain(8, 0.1, 0.016 * faceDirection());
    Eigen::Matrix3Xd v(3, x.cols());
    for (int i = 0; i < v.cols(); ++i) {
        v.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    const ContactResult& r = contact.compute(x, v, Eigen::Matrix3Xd(), kRadius, mesh.vertices, wallV);
    ASSERT_GE(r.contacts.size(), 7u);  // one per segment at least
    const Eigen::Vector3d total = r.scopeForces.rowwise().sum() + r.wallForces.rowwise().sum();
    const double scale = r.scopeForces.colwise().norm().sum();
    EXPECT_GT(scale, 1.0);
    EXPECT_LT(total.norm(), 1e-12 * scale) << "momentum balance, rounding of the sums";
    const double mu = contact.parameters().frictionCoefficient;
    double maxForce = 0.0;
    for (const ScopeContact& c : r.contacts) {
        EXPECT_GT(c.depth, 0.0);
        EXPECT_GE(c.normalForce, 0.0);
        EXPECT_LE(c.frictionForce.norm(), mu * c.normalForce * (1.0 + 1e-12));
        EXPECT_NEAR(c.frictionForce.dot(c.normal), 0.0, 1e-12);
        maxForce = std::max(maxForce, (c.normalForce * c.normal + c.frictionForce).norm());
    }
    EXPECT_DOUBLE_EQ(r.maxWallForce, maxForce);
}

/// Sliding along the tube at `speed` (m/s) against the still wall: returns the ratio |f_t| / (mu f_n).
struct SlidingCase {
    double speed;
    double expectedRatio;
};
class FrictionLaw : public ::testing::TestWithParam<SlidingCase> {};

TEST_P(FrictionLaw, SlidesAtMuOrSticksBelowTheVelocityScale)
{
    const geometry::TriangleMesh mesh = tube();
    ScopeWallContact contact(mesh);
    const Eigen::Matrix3Xd x = chain(4, 0.1, 0.015 * faceDirection());
    Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, x.cols());
    v.row(2).setConstant(GetParam().speed);
    const Eigen::Matrix3Xd wallV = Eigen::Matrix3Xd::Zero(3, mesh.numVertices());
    const ContactResult& r = contact.compute(x, v, Eigen::Matrix3Xd(), kRadius, mesh.vertices, wallV);
    ASSERT_FALSE(r.contacts.empty());
    const double mu = contact.parameters().frictionCoefficient;
    for (const ScopeContact& c : r.contacts) {
        ASSERT_GT(c.normalForce, 0.0);
        // Regularised Coulomb: |f_t| = mu f_n min(1, |v_t| / v_s), v_t the sliding velocity
        // tangential to this contact's normal (edge contacts at the chain's ends tilt it).
        const Eigen::Vector3d vt = v.col(0) - v.col(0).dot(c.normal) * c.normal;
        const double ratio = c.frictionForce.norm() / (mu * c.normalForce);
        EXPECT_NEAR(ratio, std::min(1.0, vt.norm() / contact.parameters().stickVelocity), 1e-9);
        EXPECT_LE(ratio, GetParam().expectedRatio + 1e-9);
        EXPECT_LT(c.frictionForce.z(), 0.0) << "opposes the sliding";
    }
}

INSTANTIATE_TEST_SUITE_P(Speeds, FrictionLaw,
                         ::testing::Values(SlidingCase{0.1, 1.0}, SlidingCase{0.5, 1.0},
                                           SlidingCase{0.011, 1.0},  // just above v_s = 0.01 m/s
                                           SlidingCase{1e-3, 0.1}, SlidingCase{1e-4, 0.01}));

/// A two-node probe (50 g per node) pressed on a wall face by 5 N and pulled
/// along the tube by `pull` N for `seconds`; returns its final axial speed.
double pulledProbeSpeed(double pull, double seconds)
{
    const geometry::TriangleMesh mesh = tube();
    ScopeWallContact contact(mesh);
    const double mass = 0.05;
    Eigen::Matrix3Xd x = chain(2, 0.15, 0.0125 * faceDirection());
    Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, 2);
    const Eigen::Matrix3Xd wallV = Eigen::Matrix3Xd::Zero(3, mesh.numVertices());
    const Eigen::Vector3d load = 2.5 * faceDirection() + Eigen::Vector3d(0.0, 0.0, 0.5 * pull);
    for (int step = 0; step < static_cast<int>(seconds / kDt); ++step) {
        const ContactResult& r = contact.compute(x, v, Eigen::Matrix3Xd(), kRadius, mesh.vertices, wallV);
        for (int i = 0; i < 2; ++i) {
            v.col(i) += kDt / mass * (r.scopeForces.col(i) + load);
            x.col(i) += kDt * v.col(i);
        }
    }
    return v.row(2).mean();
}

TEST(ScopeWallContact, SticksBelowTheFrictionLimitAndSlipsAbove)
{
    // mu f_n = 0.5 N. Below it, the regularised law lets the probe creep at
    // v_s pull / (mu f_n) = 6 mm/s; 10% margin for the settling of the normal force.
    const double vs = ContactParameters{}.stickVelocity;
    const double creep = pulledProbeSpeed(0.3, 1.0);
    EXPECT_GT(creep, 0.0);
    EXPECT_LT(creep, 1.1 * vs * 0.3 / 0.5);
    // Above it, the excess 0.2 N accelerates the 0.1 kg probe at 2 m/s^2: 0.4 m/s after 0.2 s (10%).
    EXPECT_NEAR(pulledProbeSpeed(0.7, 0.2), 0.4, 0.04);
}

struct DriveCase {
    double speed;    ///< m/s, towards the wall
    bool kinematic;  ///< positions prescribed (else a mass-spring probe on the penalty)
};
class NoTunnelling : public ::testing::TestWithParam<DriveCase> {};

TEST_P(NoTunnelling, ChainPushedIntoTheWallStaysInside)
{
    const geometry::TriangleMesh mesh = tube();
    ScopeWallContact contact(mesh);
    const Eigen::Vector3d dir = faceDirection();
    const Eigen::Matrix3Xd start = chain(5, 0.1, Eigen::Vector3d::Zero());
    Eigen::Matrix3Xd x = start;
    Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, x.cols());
    Eigen::Matrix3Xd previous = x;
    const Eigen::Matrix3Xd wallV = Eigen::Matrix3Xd::Zero(3, mesh.numVertices());
    const double speed = GetParam().speed;
    const double travel = 0.07;  // the drive ends 5 cm beyond the wall
    // Explicit (symplectic Euler) probe: stable while k_c dt^2 / m and the stick
    // damping mu f_n dt / (v_s m) stay below 2, hence 50 g nodes.
    const double mass = 0.05;    // kg per probe node
    const double drive = 100.0;  // N/m, probe node to its driven point: 5 N per node at the end
    int crossings = 0;
    double deepest = 0.0;
    for (int step = 1; step <= static_cast<int>(travel / (speed * kDt)); ++step) {
        previous = x;
        if (GetParam().kinematic) {
            x.colwise() += speed * kDt * dir;
            v.colwise() = speed * dir;
        }
        const ContactResult& r = contact.compute(x, v, previous, kRadius, mesh.vertices, wallV);
        crossings += static_cast<int>(r.crossings.size());
        for (const ScopeContact& c : r.contacts) {
            deepest = std::max(deepest, c.depth);
        }
        if (GetParam().kinematic) {
            pushBackCrossedNodes(r, x, v);
        } else {
            const Eigen::Vector3d target = speed * kDt * step * dir;
            for (int i = 0; i < x.cols(); ++i) {
                const Eigen::Vector3d spring = drive * (start.col(i) + target - x.col(i));
                v.col(i) += kDt / mass * (r.scopeForces.col(i) + spring);
                x.col(i) += kDt * v.col(i);
            }
        }
        for (int i = 0; i < x.cols(); ++i) {
            ASSERT_GE(insideMargin(mesh, x.col(i)), 0.0) << "node " << i << " outside at step " << step;
        }
    }
    if (GetParam().kinematic) {
        EXPECT_GT(crossings, 0) << "the prescribed motion does reach the wall";
        EXPECT_GT(deepest, kRadius) << "crossings act as deep contacts";
    } else {
        EXPECT_EQ(crossings, 0);
        // 5 N per node on k_c = 1e4 N/m: about 0.5 mm at rest, more at the impact;
        // the penalty alone keeps the axis on the lumen side (depth < r).
        EXPECT_GT(deepest, 3e-4);
        EXPECT_LT(deepest, kRadius);
    }
}

INSTANTIATE_TEST_SUITE_P(Speeds, NoTunnelling,
                         ::testing::Values(DriveCase{0.5, true}, DriveCase{2.0, true}, DriveCase{0.5, false},
                                           DriveCase{2.0, false}));

}  // namespace
}  // namespace colonosim::contact
