// Rodrigues' coefficients and the rotation they give, against libm's sin and
// cos: the series the chain solver uses below 0.6 rad must be exact to
// rounding, and its switch to sin/cos must not show.

#include "simcore/scope/Rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using colonosim::scope::rodriguesCoefficients;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// (a, b) in closed form, in long double so that its own rounding stays
/// below the tolerance; b as 2 sin^2(t/2) / t^2, which does not cancel near 0.
Eigen::Array2d closedForm(double t)
{
    const long double tl = t;
    const long double half = std::sin(0.5L * tl) / (0.5L * tl);
    return {static_cast<double>(std::sin(tl) / tl), static_cast<double>(0.5L * half * half)};
}

TEST(Rotation, SeriesCoefficientsAgreeWithSinAndCosToTwoUlps)
{
    double worstA = 0.0;
    double worstB = 0.0;
    // Uniform in t up to the switch, and dense near zero.
    for (int i = 1; i <= 6000; ++i) {
        const double t = i <= 3000 ? 0.6 * i / 3000.0 : 1e-3 * (i - 3000) / 3000.0;
        if (!(t * t < 0.36)) {
            continue;
        }
        const Eigen::Array2d series = rodriguesCoefficients(t * t);
        const Eigen::Array2d exact = closedForm(t);
        worstA = std::max(worstA, std::abs(series.x() - exact.x()) / exact.x());
        worstB = std::max(worstB, std::abs(series.y() - exact.y()) / exact.y());
    }
    EXPECT_LE(worstA, 2.0 * kEpsilon);
    EXPECT_LE(worstB, 2.0 * kEpsilon);
    EXPECT_GT(worstA + worstB, 0.0);  // the comparison saw rounding, not a copy of itself
}

TEST(Rotation, SwitchFromSeriesToSinAndCosIsContinuousToRounding)
{
    const double below = std::nextafter(0.36, 0.0);
    const Eigen::Array2d series = rodriguesCoefficients(below);
    const Eigen::Array2d trig = rodriguesCoefficients(0.36);
    EXPECT_NEAR(series.x(), trig.x(), 4.0 * kEpsilon);
    EXPECT_NEAR(series.y(), trig.y(), 4.0 * kEpsilon);
    const Eigen::Array2d exact = closedForm(0.6);
    EXPECT_NEAR(trig.x(), exact.x(), 4.0 * kEpsilon);
    EXPECT_NEAR(trig.y(), exact.y(), 4.0 * kEpsilon);
}

TEST(Rotation, RotationIsOrthonormalAndInvertsThroughTheLogarithm)
{
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const Eigen::Vector3d axis = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
        const double angle = 1.5 * std::abs(unit(random));
        const Eigen::Vector3d theta = angle * axis;
        const Eigen::Matrix3d r = colonosim::scope::rotationFromVector(theta);
        EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-14) << theta.transpose();
        EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
        const Eigen::Matrix3d eigenR = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        EXPECT_LT((r - eigenR).norm(), 1e-15) << theta.transpose();
        EXPECT_LT((colonosim::scope::vectorFromRotation(r) - theta).norm(), 1e-13) << theta.transpose();
    }
}

}  // namespace
