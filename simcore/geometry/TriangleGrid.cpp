#include "simcore/geometry/TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colonosim::geometry {

Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                       Eigen::Vector3d* bary)
{
    const auto out = [bary](double u, double v, double w, const Eigen::Vector3d& q) {
        if (bary != nullptr) {
            *bary = Eigen::Vector3d(u, v, w);
        }
        return q;
    };
    const Eigen::Vector3d ab = b - a;
    const Eigen::Vector3d ac = c - a;
    const Eigen::Vector3d ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0)
        return out(1, 0, 0, a);
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3)
        return out(0, 1, 0, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return out(1 - v, v, 0, a + v * ab);
    }
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6)
        return out(0, 0, 1, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return out(1 - w, 0, w, a + w * ac);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return out(0, 1 - w, w, b + w * (c - b));
    }
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom;
    const double w = vc * denom;
    return out(1 - v - w, v, w, a + ab * v + ac * w);
}

TriangleGrid::TriangleGrid(const TriangleMesh& mesh) : m_mesh(&mesh)
{
    const Eigen::Vector3d lo = mesh.vertices.rowwise().minCoeff();
    const Eigen::Vector3d hi = mesh.vertices.rowwise().maxCoeff();
    double edgeSum = 0.0;
    for (const auto& t : mesh.triangles) {
        edgeSum += (mesh.vertices.col(t[1]) - mesh.vertices.col(t[0])).norm();
    }
    m_cellSize = std::max(edgeSum / std::max<std::size_t>(1, mesh.triangles.size()), 1e-6);
    const Eigen::Vector3d extent = (hi - lo).cwiseMax(1e-9);
    m_cellSize = std::max(m_cellSize, std::cbrt(extent.prod() / 2.0e6));
    m_origin = lo;
    m_dims = ((extent / m_cellSize).array().floor().cast<int>() + 1).matrix();

    const int numCells = m_dims.prod();
    std::vector<int> counts(static_cast<std::size_t>(numCells) + 1, 0);
    const auto forEachCell = [&](const std::array<int, 3>& t, auto&& visit) {
        const Eigen::Vector3d a = mesh.vertices.col(t[0]);
        const Eigen::Vector3d b = mesh.vertices.col(t[1]);
        const Eigen::Vector3d c = mesh.vertices.col(t[2]);
        const Eigen::Vector3i c0 = cellOf(a.cwiseMin(b).cwiseMin(c));
        const Eigen::Vector3i c1 = cellOf(a.cwiseMax(b).cwiseMax(c));
        for (int z = c0.z(); z <= c1.z(); ++z)
            for (int y = c0.y(); y <= c1.y(); ++y)
                for (int x = c0.x(); x <= c1.x(); ++x)
                    visit(cellIndex(x, y, z));
    };
    for (const auto& t : mesh.triangles) {
        forEachCell(t, [&](int cell) { ++counts[static_cast<std::size_t>(cell) + 1]; });
    }
    for (int i = 0; i < numCells; ++i) {
        counts[static_cast<std::size_t>(i) + 1] += counts[static_cast<std::size_t>(i)];
    }
    m_cellStart = counts;
    m_cellTriangles.resize(static_cast<std::size_t>(counts.back()));
    for (int ti = 0; ti < static_cast<int>(mesh.triangles.size()); ++ti) {
        forEachCell(mesh.triangles[static_cast<std::size_t>(ti)], [&](int cell) {
            m_cellTriangles[static_cast<std::size_t>(counts[static_cast<std::size_t>(cell)]++)] = ti;
        });
    }
}

Eigen::Vector3i TriangleGrid::cellOf(const Eigen::Vector3d& p) const
{
    const Eigen::Vector3d f = (p - m_origin) / m_cellSize;
    return Eigen::Vector3i(std::clamp(static_cast<int>(std::floor(f.x())), 0, m_dims.x() - 1),
                           std::clamp(static_cast<int>(std::floor(f.y())), 0, m_dims.y() - 1),
                           std::clamp(static_cast<int>(std::floor(f.z())), 0, m_dims.z() - 1));
}

void TriangleGrid::nearest(const Eigen::Vector3d& p, double slack, std::vector<Candidate>& out) const
{
    out.clear();
    const TriangleMesh& mesh = *m_mesh;
    const Eigen::Vector3i home = cellOf(p);
    // Distance from p to the grid box, so shells are counted from where p enters it.
    const Eigen::Vector3d boxLo = m_origin;
    const Eigen::Vector3d boxHi = m_origin + m_dims.cast<double>() * m_cellSize;
    const double outside = (boxLo - p).cwiseMax(p - boxHi).cwiseMax(0.0).norm();
    double best = std::numeric_limits<double>::infinity();
    const int maxShell = m_dims.maxCoeff();
    for (int k = 0; k <= maxShell; ++k) {
        for (int z = home.z() - k; z <= home.z() + k; ++z) {
            for (int y = home.y() - k; y <= home.y() + k; ++y) {
                for (int x = home.x() - k; x <= home.x() + k; ++x) {
                    if (std::max({std::abs(x - home.x()), std::abs(y - home.y()), std::abs(z - home.z())}) !=
                        k)
                        continue;
                    if (x < 0 || y < 0 || z < 0 || x >= m_dims.x() || y >= m_dims.y() || z >= m_dims.z())
                        continue;
                    const int cell = cellIndex(x, y, z);
                    for (int i = m_cellStart[static_cast<std::size_t>(cell)];
                         i < m_cellStart[static_cast<std::size_t>(cell) + 1]; ++i) {
                        const int ti = m_cellTriangles[static_cast<std::size_t>(i)];
                        const auto& t = mesh.triangles[static_cast<std::size_t>(ti)];
                        const double d =
                            (closestPointOnTriangle(p, mesh.vertices.col(t[0]), mesh.vertices.col(t[1]),
                                                    mesh.vertices.col(t[2]), nullptr) -
                             p)
                                .norm();
                        best = std::min(best, d);
                        if (d <= best + slack) {
                            out.push_back({ti, d});
                        }
                    }
                }
            }
        }
        if (best + slack <= outside + k * m_cellSize) {
            break;
        }
    }
    const auto cut =
        std::remove_if(out.begin(), out.end(), [&](const Candidate& c) { return c.distance > best + slack; });
    out.erase(cut, out.end());
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
        return a.distance < b.distance || (a.distance == b.distance && a.triangle < b.triangle);
    });
    out.erase(std::unique(out.begin(), out.end(),
                          [](const Candidate& a, const Candidate& b) { return a.triangle == b.triangle; }),
              out.end());
}

}  // namespace colonosim::geometry
