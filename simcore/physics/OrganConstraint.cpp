#include "simcore/physics/OrganConstraint.h"

namespace colonosim::physics {

using geometry::ImplicitShape;

OrganConstraint::OrganConstraint(std::vector<ImplicitShape> shapes) : m_shapes(std::move(shapes))
{
    for (const ImplicitShape& shape : m_shapes) {
        Bounds b{};
        if (shape.kind == ImplicitShape::Kind::Ellipsoid) {
            b.centre = shape.centre;
            b.outerRadius = shape.semiAxes.maxCoeff();
            b.innerRadius = shape.semiAxes.minCoeff();
            b.inverseSemiAxes = shape.semiAxes.cwiseInverse();
        } else {
            b.centre = 0.5 * (shape.capsuleA + shape.capsuleB);
            const double half = 0.5 * (shape.capsuleB - shape.capsuleA).norm();
            b.outerRadius = half + shape.capsuleRadius;
            b.innerRadius = shape.capsuleRadius > half ? shape.capsuleRadius - half : 0.0;
        }
        m_bounds.push_back(b);
    }
}

int OrganConstraint::project(std::span<const int> nodes, Positions& x, Velocities& v) const
{
    int corrected = 0;
    for (size_t s = 0; s < m_shapes.size(); ++s) {
        const ImplicitShape& shape = m_shapes[s];
        const Bounds& b = m_bounds[s];
        const bool keepOutside = shape.side == ImplicitShape::Side::KeepOutside;
        const double outer2 = b.outerRadius * b.outerRadius;
        const double inner2 = b.innerRadius * b.innerRadius;
        for (const int i : nodes) {
            const double r2 = (x.col(i) - b.centre).squaredNorm();
            if (keepOutside ? r2 >= outer2 : r2 <= inner2) {
                continue;  // certainly allowed
            }
            if (shape.kind == ImplicitShape::Kind::Ellipsoid) {
                // Side of the surface: the sign of the signed distance is that of k0 - 1.
                const double k02 = (x.col(i) - b.centre).cwiseProduct(b.inverseSemiAxes).squaredNorm();
                if (keepOutside ? k02 >= 1.0 : k02 <= 1.0) {
                    continue;
                }
            }
            Eigen::Vector3d push;
            const double depth = shape.penetration(x.col(i), &push);
            if (depth > 0.0) {
                x.col(i) += depth * push;
                const double into = v.col(i).dot(push);
                if (into < 0.0) {
                    v.col(i) -= into * push;
                }
                ++corrected;
            }
        }
    }
    return corrected;
}

}  // namespace colonosim::physics
