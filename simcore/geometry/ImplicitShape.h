#pragma once
/// \file
/// Surrounding organs and the abdominal wall as implicit shapes that the colon
/// wall may not penetrate. A shape either keeps points outside (an organ) or
/// inside (the abdominal cavity).

#include <Eigen/Core>

#include <string>

namespace colonosim::geometry {

struct ImplicitShape {
    enum class Kind { Ellipsoid, Capsule };
    enum class Side { KeepOutside, KeepInside };

    std::string name;
    Kind kind = Kind::Ellipsoid;
    Side side = Side::KeepOutside;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();    ///< ellipsoid centre, m
    Eigen::Vector3d semiAxes = Eigen::Vector3d::Ones();  ///< ellipsoid semi-axes along x, y, z, m
    Eigen::Vector3d capsuleA = Eigen::Vector3d::Zero();  ///< capsule segment end, m
    Eigen::Vector3d capsuleB = Eigen::Vector3d::Zero();  ///< capsule segment end, m
    double capsuleRadius = 0.0;                          ///< m

    /// Signed distance to the surface (m), negative inside the shape, with the
    /// outward unit gradient. For ellipsoids it is a first-order approximation
    /// that is exact on the surface and has the right sign everywhere.
    [[nodiscard]] double signedDistance(const Eigen::Vector3d& p, Eigen::Vector3d* gradient) const;

    /// Penetration depth (m, >= 0) of `p` into the forbidden region, and the
    /// unit direction that leads back to the allowed region.
    [[nodiscard]] double penetration(const Eigen::Vector3d& p, Eigen::Vector3d* pushDirection) const;
};

}  // namespace colonosim::geometry
