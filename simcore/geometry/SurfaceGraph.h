#pragma once
/// \file
/// The edge graph of a triangle mesh, for geodesic distances along the
/// surface: compressed rows of neighbours with edge lengths, the boundary
/// edges (used by exactly one triangle), Dijkstra from several sources
/// (O(E log V)) and the open boundary loops of a tube (its open ends).

#include "simcore/geometry/TriangleMesh.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace colonosim::geometry::surface {

/// Undirected edge graph in compressed rows, plus the boundary edges.
struct EdgeGraph {
    std::vector<int> offset;  ///< numVertices + 1
    std::vector<int> neighbour;
    std::vector<double> length;
    std::vector<std::pair<int, int>> boundary;  ///< edges used by exactly one triangle
    double meanEdge = 0.0;
};

[[nodiscard]] EdgeGraph buildGraph(const TriangleMesh& mesh);
/// Shortest distance along edges from the nearest source; +infinity where unreachable.
[[nodiscard]] std::vector<double> geodesic(const EdgeGraph& g, const std::vector<int>& sources);
/// Index of the largest finite entry (-1 if none).
[[nodiscard]] int argmaxFinite(const std::vector<double>& d);
/// Open boundary loops (connected sets of boundary edges), longest first.
[[nodiscard]] std::vector<std::vector<int>> boundaryLoops(const EdgeGraph& g, std::size_t numV);

}  // namespace colonosim::geometry::surface
