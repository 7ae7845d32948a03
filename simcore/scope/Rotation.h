#pragma once
/// \file
/// Exact rotations of the discrete rod: the exponential map (Rodrigues'
/// formula) R(theta) = I + a [theta]x + b [theta]x^2, a = sin t / t,
/// b = (1 - cos t) / t^2, t = |theta|; its inverse (the logarithm); and the
/// inverse right Jacobian of the exponential, used by the reference solver's
/// energy gradient: log(R(theta) exp(delta)) = theta + Jr^-1(theta) delta + O(delta^2).
/// Source: standard SO(3) identities (e.g. Sola et al., "A micro Lie theory", 2018).
///
/// Per-joint angles of the rod are small (a few hundredths of a radian, up to
/// a few tenths in a tight bend), so a and b are evaluated by their Taylor
/// series below 0.6 rad, as polynomials in t^2 with precomputed coefficients,
/// truncated where the next term is below double precision: exact to
/// rounding, with neither the sin/cos calls nor the divisions that would
/// dominate the chain solver's cost.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace colonosim::scope {

/// The skew-symmetric matrix [v]x with [v]x w = v x w.
[[nodiscard]] inline Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return s;
}

namespace detail {

/// 1 / n!, rounded once.
[[nodiscard]] constexpr double inverseFactorial(int n)
{
    double f = 1.0;
    for (int k = 2; k <= n; ++k) {
        f *= k;  // exact up to 22!
    }
    return 1.0 / f;
}

/// The Taylor coefficients of a = sin t / t and b = (1 - cos t) / t^2 in t^2:
/// a = sum_k (-1)^k t^2k / (2k+1)!, b = sum_k (-1)^k t^2k / (2k+2)!, k = 0..7.
/// Below t = 0.6 the first omitted terms, t^16/17! and t^16/18!, are under
/// 8e-19 and 5e-20: below half an ulp of a (> 0.94) and b (> 0.48).
inline constexpr double kRodriguesSeriesLimit2 = 0.36;  ///< t^2 below which the series is used, rad^2

[[nodiscard]] constexpr double rodriguesSeriesA(int k)
{
    return (k % 2 == 0 ? 1.0 : -1.0) * inverseFactorial(2 * k + 1);
}

[[nodiscard]] constexpr double rodriguesSeriesB(int k)
{
    return (k % 2 == 0 ? 1.0 : -1.0) * inverseFactorial(2 * k + 2);
}

/// (a, b) by the series above (exact to rounding below kRodriguesSeriesLimit2),
/// both in one Array2d (two-lane arithmetic), by Estrin's scheme: pairs of
/// terms, then pairs of pairs, so that the multiplications wait on three
/// levels rather than on Horner's eight.
[[nodiscard]] inline Eigen::Array2d rodriguesSeries(double t2)
{
    const auto c = [](int k) { return Eigen::Array2d(rodriguesSeriesA(k), rodriguesSeriesB(k)); };
    const double t4 = t2 * t2;
    const double t8 = t4 * t4;
    const Eigen::Array2d p01 = c(0) + c(1) * t2;
    const Eigen::Array2d p23 = c(2) + c(3) * t2;
    const Eigen::Array2d p45 = c(4) + c(5) * t2;
    const Eigen::Array2d p67 = c(6) + c(7) * t2;
    const Eigen::Array2d p03 = p01 + p23 * t4;
    const Eigen::Array2d p47 = p45 + p67 * t4;
    return p03 + p47 * t8;
}

}  // namespace detail

/// Rodrigues' coefficients (a, b) of R(theta) for t2 = |theta|^2: the
/// series below t = 0.6 rad; above, sin and cos, with the two divisions
/// paired in one two-lane division.
[[nodiscard]] inline Eigen::Array2d rodriguesCoefficients(double t2)
{
    if (t2 < detail::kRodriguesSeriesLimit2) {
        return detail::rodriguesSeries(t2);
    }
    const double t = std::sqrt(t2);
    return Eigen::Array2d(std::sin(t), 1.0 - std::cos(t)) / Eigen::Array2d(t, t2);
}

/// R(theta) from its Rodrigues' coefficients ab = (a, b).
[[nodiscard]] inline Eigen::Matrix3d rotationFromCoefficients(const Eigen::Vector3d& theta,
                                                              const Eigen::Array2d& ab)
{
    const double a = ab.x();
    const double b = ab.y();
    const double x = theta.x();
    const double y = theta.y();
    const double z = theta.z();
    Eigen::Matrix3d r;
    r << 1.0 - b * (y * y + z * z), -a * z + b * x * y, a * y + b * x * z,  //
        a * z + b * x * y, 1.0 - b * (x * x + z * z), -a * x + b * y * z,   //
        -a * y + b * x * z, a * x + b * y * z, 1.0 - b * (x * x + y * y);
    return r;
}

/// R(theta) = exp([theta]x), Rodrigues' formula.
[[nodiscard]] inline Eigen::Matrix3d rotationFromVector(const Eigen::Vector3d& theta)
{
    return rotationFromCoefficients(theta, rodriguesCoefficients(theta.squaredNorm()));
}

/// The rotation vector theta with R = exp([theta]x), |theta| <= pi.
[[nodiscard]] inline Eigen::Vector3d vectorFromRotation(const Eigen::Matrix3d& r)
{
    const Eigen::Vector3d w(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
    const double c = std::clamp(0.5 * (r.trace() - 1.0), -1.0, 1.0);
    const double s = 0.5 * w.norm();
    const double t = std::atan2(s, c);
    if (t < 1e-6) {
        return 0.5 * (1.0 + t * t / 6.0) * w;
    }
    if (t < 3.1) {
        return (t / (2.0 * s)) * w;
    }
    // Near pi: the axis from the symmetric part, the sign from w.
    const Eigen::Matrix3d sym = 0.5 * (r + r.transpose()) - c * Eigen::Matrix3d::Identity();
    Eigen::Index col = 0;
    sym.diagonal().maxCoeff(&col);
    Eigen::Vector3d axis = sym.col(col).normalized();
    if (axis.dot(w) < 0.0) {
        axis = -axis;
    }
    return t * axis;
}

/// The inverse right Jacobian of the exponential map at theta.
[[nodiscard]] inline Eigen::Matrix3d inverseRightJacobian(const Eigen::Vector3d& theta)
{
    const double t2 = theta.squaredNorm();
    const Eigen::Matrix3d s = skew(theta);
    double c = 1.0 / 12.0 + t2 / 720.0;
    if (t2 > 1e-4) {
        const double t = std::sqrt(t2);
        c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
    }
    return Eigen::Matrix3d::Identity() + 0.5 * s + c * s * s;
}

}  // namespace colonosim::scope
