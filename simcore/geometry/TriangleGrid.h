#pragma once
/// \file
/// Uniform spatial grid over the triangles of a mesh, for nearest-triangle
/// queries. Each triangle is listed in every cell its bounding box overlaps
/// (compressed rows). A query visits shells of cells of growing Chebyshev
/// radius k around the query's cell and stops once the best distance found is
/// at most k cell sizes, since every unvisited triangle is farther.
/// Closest point on a triangle: Ericson, Real-Time Collision Detection, 5.1.5.

#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::geometry {

/// Closest point of triangle (a, b, c) to p, with its barycentric coordinates.
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                       Eigen::Vector3d* barycentric);

class TriangleGrid {
public:
    struct Candidate {
        int triangle = -1;
        double distance = 0.0;  ///< m
    };

    /// Cell size: the mean edge length, enlarged so there are at most ~2 M cells.
    explicit TriangleGrid(const TriangleMesh& mesh);

    /// Triangles whose distance to p is within `slack` of the nearest one,
    /// nearest first.
    void nearest(const Eigen::Vector3d& p, double slack, std::vector<Candidate>& out) const;

    [[nodiscard]] double cellSize() const { return m_cellSize; }

private:
    [[nodiscard]] Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;
    [[nodiscard]] int cellIndex(int x, int y, int z) const { return (z * m_dims.y() + y) * m_dims.x() + x; }

    const TriangleMesh* m_mesh;
    Eigen::Vector3d m_origin;
    Eigen::Vector3i m_dims;
    double m_cellSize = 1.0;
    std::vector<int> m_cellStart;  ///< size numCells + 1
    std::vector<int> m_cellTriangles;
};

}  // namespace colonosim::geometry
