#pragma once
/// \file
/// Exact rotations of the discrete rod: the exponential map (Rodrigues'
/// formula) R(theta) = I + a [theta]x + b [theta]x^2, a = sin t / t,
/// b = (1 - cos t) / t^2, t = |theta|; its inverse (the logarithm); and the
/// inverse right Jacobian of the exponential, used by the reference solver's
/// energy gradient: log(R(theta) exp(delta)) = theta + Jr^-1(theta) delta + O(delta^2).
/// Source: standard SO(3) identities (e.g. Sola et al., "A micro Lie theory", 2018).
///
/// Per-joint angles of the rod are small (a few hundredths of a radian), so a
/// and b are evaluated by their Taylor series below 0.05 rad, truncated where
/// the next term is below double precision: exact to rounding, and without
/// the sin/cos calls that would dominate the chain solver's cost.

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

/// Rodrigues' coefficients (a, b) of R(theta) for t2 = |theta|^2. The two
/// are computed side by side in one Array2d, so each pair of divisions (the
/// series' t2 / c, or sin t / t and (1 - cos t) / t2) is a single two-lane
/// division: the same correctly rounded quotients as one at a time, in half
/// the divider's time, which dominates this function.
[[nodiscard]] inline Eigen::Array2d rodriguesCoefficients(double t2)
{
    if (t2 < 2.5e-3) {
        // t < 0.05: next omitted terms are t^10/11! and t^10/12!, below 1e-21.
        // a = 1 - t2/6 (1 - t2/20 (1 - t2/42 (1 - t2/72))),
        // b = (1 - t2/12 (1 - t2/30 (1 - t2/56 (1 - t2/90)))) / 2, from the innermost bracket out.
        Eigen::Array2d series = 1.0 - t2 / Eigen::Array2d(72.0, 90.0);
        series = 1.0 - (t2 / Eigen::Array2d(42.0, 56.0)) * series;
        series = 1.0 - (t2 / Eigen::Array2d(20.0, 30.0)) * series;
        series = 1.0 - (t2 / Eigen::Array2d(6.0, 12.0)) * series;
        return {series.x(), 0.5 * series.y()};
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
