#pragma once
/// \file
/// Surrounding organs and the abdominal wall as non-penetrable implicit
/// shapes (geometry::ImplicitShape). After each step a node found inside an
/// organ (or outside the abdominal cavity) is projected back to the surface
/// and loses the velocity component that points into the shape (inelastic,
/// frictionless contact). A bounding-sphere test skips far shapes cheaply;
/// for an ellipsoid the exact side test |(p - c) / a| vs 1 (the sign of its
/// signed distance) skips the allowed nodes before the distance is computed.

#include "simcore/geometry/ImplicitShape.h"
#include "simcore/physics/Constraint.h"

#include <vector>

namespace colonosim::physics {

class OrganConstraint final : public Constraint {
public:
    explicit OrganConstraint(std::vector<geometry::ImplicitShape> shapes);

    [[nodiscard]] std::string_view name() const override { return "organs"; }
    int project(std::span<const int> nodes, Positions& x, Velocities& v) const override;
    [[nodiscard]] const std::vector<geometry::ImplicitShape>& shapes() const { return m_shapes; }

private:
    struct Bounds {
        Eigen::Vector3d centre;
        double outerRadius;                                         ///< sphere containing the shape, m
        double innerRadius;                                         ///< sphere contained in the shape, m
        Eigen::Vector3d inverseSemiAxes = Eigen::Vector3d::Zero();  ///< ellipsoids, 1/m
    };
    std::vector<geometry::ImplicitShape> m_shapes;
    std::vector<Bounds> m_bounds;
};

}  // namespace colonosim::physics
