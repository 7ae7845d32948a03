#include "simcore/geometry/ImplicitShape.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::geometry {
namespace {

ImplicitShape ellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& axes)
{
    ImplicitShape s;
    s.kind = ImplicitShape::Kind::Ellipsoid;
    s.centre = centre;
    s.semiAxes = axes;
    return s;
}

ImplicitShape capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r)
{
    ImplicitShape s;
    s.kind = ImplicitShape::Kind::Capsule;
    s.capsuleA = a;
    s.capsuleB = b;
    s.capsuleRadius = r;
    return s;
}

struct DistanceCase {
    const char* name;
    ImplicitShape shape;
    Eigen::Vector3d point;
    double expected;           ///< exact signed distance, m
    double tolerance;          ///< m; 1e-12 where the formula is exact
    Eigen::Vector3d gradient;  ///< expected outward unit gradient
};

class SignedDistance : public ::testing::TestWithParam<DistanceCase> {};

TEST_P(SignedDistance, ValueSignAndGradient)
{
    const DistanceCase& c = GetParam();
    Eigen::Vector3d gradient;
    const double d = c.shape.signedDistance(c.point, &gradient);
    EXPECT_NEAR(d, c.expected, c.tolerance);
    if (c.expected != 0.0) {
        EXPECT_EQ(std::signbit(d), std::signbit(c.expected)) << "wrong side";
    }
    EXPECT_NEAR((gradient - c.gradient).norm(), 0.0, 1e-9);
}

const Eigen::Vector3d kC(0.1, 0.2, 0.3);
const Eigen::Vector3d kAxes(0.10, 0.05, 0.02);

INSTANTIATE_TEST_SUITE_P(
    Table, SignedDistance,
    ::testing::Values(
        // A sphere is an ellipsoid with equal axes: the formula is exact everywhere.
        DistanceCase{"sphereOutside", ellipsoid(kC, Eigen::Vector3d::Constant(0.05)),
                     kC + Eigen::Vector3d(0, 0.08, 0), 0.03, 1e-12, Eigen::Vector3d::UnitY()},
        DistanceCase{"sphereInside", ellipsoid(kC, Eigen::Vector3d::Constant(0.05)),
                     kC + Eigen::Vector3d(-0.02, 0, 0), -0.03, 1e-12, -Eigen::Vector3d::UnitX()},
        // On the surface the ellipsoid distance is exact (0) and the gradient is the surface normal.
        DistanceCase{"ellipsoidSurfaceX", ellipsoid(kC, kAxes), kC + Eigen::Vector3d(0.10, 0, 0), 0.0, 1e-12,
                     Eigen::Vector3d::UnitX()},
        DistanceCase{"ellipsoidSurfaceZ", ellipsoid(kC, kAxes), kC + Eigen::Vector3d(0, 0, -0.02), 0.0, 1e-12,
                     -Eigen::Vector3d::UnitZ()},
        // Along a principal axis the first-order formula is exact too.
        DistanceCase{"ellipsoidAxisOutside", ellipsoid(kC, kAxes), kC + Eigen::Vector3d(0, 0.09, 0), 0.04,
                     1e-12, Eigen::Vector3d::UnitY()},
        DistanceCase{"ellipsoidAxisInside", ellipsoid(kC, kAxes), kC + Eigen::Vector3d(0, 0, 0.01), -0.01,
                     1e-12, Eigen::Vector3d::UnitZ()},
        DistanceCase{"ellipsoidCentre", ellipsoid(kC, kAxes), kC, -0.02, 1e-12, Eigen::Vector3d::UnitZ()},
        DistanceCase{"capsuleSide",
                     capsule({0, 0, 0}, {0, 0, 1}, 0.1),
                     {0.3, 0, 0.5},
                     0.2,
                     1e-12,
                     Eigen::Vector3d::UnitX()},
        DistanceCase{"capsuleEnd",
                     capsule({0, 0, 0}, {0, 0, 1}, 0.1),
                     {0, 0, 1.25},
                     0.15,
                     1e-12,
                     Eigen::Vector3d::UnitZ()},
        DistanceCase{"capsuleInside",
                     capsule({0, 0, 0}, {0, 0, 1}, 0.1),
                     {0, -0.04, 0.2},
                     -0.06,
                     1e-12,
                     -Eigen::Vector3d::UnitY()}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SignedDistance, EllipsoidSignIsRightOffAxis)
{
    // Off-axis the value is approximate, but the sign must match the implicit
    // function and the gradient must be the normalised implicit gradient.
    const ImplicitShape e = ellipsoid(kC, kAxes);
    for (int i = 0; i < 200; ++i) {
        const double a = 0.1 * i;
        const double scale = 0.5 + 0.01 * i;  // from inside (0.5) to outside (2.5)
        const Eigen::Vector3d dir(std::cos(a) * std::sin(3 * a), std::sin(a) * std::sin(3 * a),
                                  std::cos(3 * a));
        const Eigen::Vector3d p = kC + scale * kAxes.cwiseProduct(dir);
        const double f = (p - kC).cwiseQuotient(kAxes).squaredNorm() - 1.0;
        Eigen::Vector3d gradient;
        const double d = e.signedDistance(p, &gradient);
        EXPECT_EQ(d < 0.0, f < 0.0) << "sample " << i;
        const Eigen::Vector3d implicitGradient = 2.0 * (p - kC).cwiseQuotient(kAxes.cwiseProduct(kAxes));
        EXPECT_NEAR((gradient - implicitGradient.normalized()).norm(), 0.0, 1e-12);
    }
}

TEST(Penetration, KeepOutsideAndKeepInside)
{
    ImplicitShape organ = ellipsoid({0, 0, 0}, Eigen::Vector3d::Constant(0.1));
    Eigen::Vector3d push;
    EXPECT_NEAR(organ.penetration({0.07, 0, 0}, &push), 0.03, 1e-12);
    EXPECT_NEAR((push - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
    EXPECT_EQ(organ.penetration({0.2, 0, 0}, &push), 0.0);

    organ.side = ImplicitShape::Side::KeepInside;
    EXPECT_EQ(organ.penetration({0.07, 0, 0}, &push), 0.0);
    EXPECT_NEAR(organ.penetration({0, 0.15, 0}, &push), 0.05, 1e-12);
    EXPECT_NEAR((push + Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-12) << "pushed back inside";
}

}  // namespace
}  // namespace colonosim::geometry
