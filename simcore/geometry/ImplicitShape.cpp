#include "simcore/geometry/ImplicitShape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace colonosim::geometry {

namespace {

Eigen::Vector3d anyUnitPerpendicular(const Eigen::Vector3d& axis)
{
    if (axis.squaredNorm() < 1e-30) {
        return Eigen::Vector3d::UnitX();
    }
    const Eigen::Vector3d other =
        std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return axis.cross(other).normalized();
}

}  // namespace

double ImplicitShape::signedDistance(const Eigen::Vector3d& p, Eigen::Vector3d* gradient) const
{
    if (kind == Kind::Capsule) {
        const Eigen::Vector3d ab = capsuleB - capsuleA;
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0.0 ? std::clamp((p - capsuleA).dot(ab) / len2, 0.0, 1.0) : 0.0;
        const Eigen::Vector3d offset = p - (capsuleA + t * ab);
        const double dist = offset.norm();
        if (gradient != nullptr) {
            *gradient = dist > 1e-15 ? Eigen::Vector3d(offset / dist) : anyUnitPerpendicular(ab);
        }
        return dist - capsuleRadius;
    }
    // Ellipsoid: d = k0 (k0 - 1) / k1 with k0 = |q / a|, k1 = |q / a^2|,
    // the first-order distance f / |grad f| of f = k0^2 - 1 scaled to be exact
    // on the surface (Quilez, "ellipsoid SDF").
    const Eigen::Vector3d q = p - centre;
    const Eigen::Vector3d qa = q.cwiseQuotient(semiAxes);
    const Eigen::Vector3d qa2 = qa.cwiseQuotient(semiAxes);
    const double k0 = qa.norm();
    const double k1 = qa2.norm();
    if (k1 < 1e-15) {
        // At the centre: the nearest surface point is along the shortest axis.
        Eigen::Index axis = 0;
        const double shortest = semiAxes.minCoeff(&axis);
        if (gradient != nullptr) {
            *gradient = Eigen::Vector3d::Unit(axis);
        }
        return -shortest;
    }
    if (gradient != nullptr) {
        *gradient = qa2 / k1;
    }
    return k0 * (k0 - 1.0) / k1;
}

double ImplicitShape::penetration(const Eigen::Vector3d& p, Eigen::Vector3d* pushDirection) const
{
    Eigen::Vector3d gradient;
    const double d = signedDistance(p, &gradient);
    if (side == Side::KeepOutside) {
        if (pushDirection != nullptr) {
            *pushDirection = gradient;
        }
        return std::max(0.0, -d);
    }
    if (pushDirection != nullptr) {
        *pushDirection = -gradient;
    }
    return std::max(0.0, d);
}

}  // namespace colonosim::geometry
