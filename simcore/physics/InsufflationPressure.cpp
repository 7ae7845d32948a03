#include "simcore/physics/InsufflationPressure.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace colonosim::physics {

InsufflationPressure::InsufflationPressure(std::vector<std::array<int, 3>> triangles, double pressure)
    : m_triangles(std::move(triangles)), m_pressure(pressure)
{
    onActiveSetChanged({});
}

void InsufflationPressure::addForce(const Positions& x, Forces& f) const
{
    const double scale = m_pressure / 6.0;  // p/3 times the 1/2 of the area vector
    for (const int t : m_active) {
        const auto& tri = m_triangles[static_cast<size_t>(t)];
        const Eigen::Vector3d x0 = x.col(tri[0]);
        const Eigen::Vector3d fn = scale * (x.col(tri[1]) - x0).cross(x.col(tri[2]) - x0);
        f.col(tri[0]) += fn;
        f.col(tri[1]) += fn;
        f.col(tri[2]) += fn;
    }
}

void InsufflationPressure::addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                               Eigen::Matrix3Xd& df) const
{
    const double scale = m_pressure / 6.0;
    for (const int t : m_active) {
        const auto& tri = m_triangles[static_cast<size_t>(t)];
        const Eigen::Vector3d e1 = x.col(tri[1]) - x.col(tri[0]);
        const Eigen::Vector3d e2 = x.col(tri[2]) - x.col(tri[0]);
        const Eigen::Vector3d de1 = dx.col(tri[1]) - dx.col(tri[0]);
        const Eigen::Vector3d de2 = dx.col(tri[2]) - dx.col(tri[0]);
        const Eigen::Vector3d dfn = scale * (de1.cross(e2) + e1.cross(de2));
        df.col(tri[0]) += dfn;
        df.col(tri[1]) += dfn;
        df.col(tri[2]) += dfn;
    }
}

void InsufflationPressure::addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow,
                                             Eigen::VectorXd& /*cRow*/) const
{
    // Each 3x3 block of the differential is (p/6) [e]x for an edge e of the
    // triangle, of norm (p/6)|e|; a node's row holds three such blocks per
    // incident triangle. Evaluated at the current shape.
    for (size_t t = 0; t < m_triangles.size(); ++t) {
        const auto& tri = m_triangles[t];
        double longest = 0.0;
        for (int k = 0; k < 3; ++k) {
            longest = std::max(longest, (x.col(tri[(k + 1) % 3]) - x.col(tri[k])).norm());
        }
        const double rowSum = 3.0 * std::abs(m_pressure) / 6.0 * longest;
        for (const int node : m_triangles[t]) {
            kRow[node] += rowSum;
        }
    }
}

void InsufflationPressure::onActiveSetChanged(const std::vector<std::uint8_t>& awake)
{
    m_active.clear();
    for (size_t t = 0; t < m_triangles.size(); ++t) {
        const auto& tri = m_triangles[t];
        const bool any = awake.empty() || awake[static_cast<size_t>(tri[0])] ||
                         awake[static_cast<size_t>(tri[1])] || awake[static_cast<size_t>(tri[2])];
        if (any) {
            m_active.push_back(static_cast<int>(t));
        }
    }
}

}  // namespace colonosim::physics
