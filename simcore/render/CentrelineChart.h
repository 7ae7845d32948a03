#pragma once
/// \file
/// The centreline chart of a wall mesh: each vertex v takes its nearest
/// centreline sample k, the arc length s = s_k + (v - c_k).t_k continued
/// along the tangent, and the clock angle theta = atan2((v - c_k).b,
/// (v - c_k).n) in that sample's rotation-minimising frame (n, b = t x n).
/// Stored as (s, r cos theta, r sin theta), r the centreline radius at k (m).

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Geometry>

#include <vector>

namespace colonosim::render {

/// Nearest centreline sample of each vertex (Euclidean). Throws
/// std::invalid_argument when the centreline has fewer than two samples.
[[nodiscard]] std::vector<int> nearestCentrelineSamples(const geometry::TriangleMesh& mesh,
                                                        const geometry::Centreline& centreline);

/// The chart above, 3 floats per vertex, from the nearest samples.
[[nodiscard]] std::vector<float> centrelineChart(const geometry::TriangleMesh& mesh,
                                                 const geometry::Centreline& centreline,
                                                 const std::vector<int>& nearestSamples);

}  // namespace colonosim::render
