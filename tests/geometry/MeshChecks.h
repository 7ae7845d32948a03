#pragma once
/// \file
/// Test helpers: topological checks on a triangle mesh.

#include "simcore/geometry/TriangleMesh.h"

#include <map>
#include <utility>

namespace colonosim::geometry::testing {

struct EdgeCounts {
    int numNonManifoldEdges = 0;   ///< undirected edges with > 2 faces
    int numBoundaryEdges = 0;      ///< undirected edges with 1 face
    int numInconsistentEdges = 0;  ///< directed edges used twice (orientation flip)
};

inline EdgeCounts countEdges(const TriangleMesh& mesh)
{
    std::map<std::pair<int, int>, int> undirected;
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)];
            const int b = t[static_cast<std::size_t>((k + 1) % 3)];
            ++undirected[{std::min(a, b), std::max(a, b)}];
            ++directed[{a, b}];
        }
    }
    EdgeCounts counts;
    for (const auto& [edge, n] : undirected) {
        counts.numNonManifoldEdges += n > 2 ? 1 : 0;
        counts.numBoundaryEdges += n == 1 ? 1 : 0;
    }
    for (const auto& [edge, n] : directed) {
        counts.numInconsistentEdges += n > 1 ? 1 : 0;
    }
    return counts;
}

}  // namespace colonosim::geometry::testing
