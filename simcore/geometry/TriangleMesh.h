#pragma once
/// \file
/// An indexed triangle mesh in metres. Triangles are counter-clockwise seen
/// from the side their normal points to; for the colon wall, normals point
/// out of the lumen (away from the centreline).

#include <Eigen/Core>

#include <array>
#include <vector>

namespace colonosim::geometry {

struct TriangleMesh {
    Eigen::Matrix3Xd vertices;                  ///< one column per vertex, m
    std::vector<std::array<int, 3>> triangles;  ///< vertex indices

    [[nodiscard]] int numVertices() const { return static_cast<int>(vertices.cols()); }
    [[nodiscard]] int numTriangles() const { return static_cast<int>(triangles.size()); }
};

}  // namespace colonosim::geometry
