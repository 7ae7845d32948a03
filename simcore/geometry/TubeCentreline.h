#pragma once
/// \file
/// Centreline of an arbitrary tube-shaped surface (an imported colon).
///
/// 1. Geodesic distance g over the edge graph (Dijkstra) from the longest open
///    boundary loop (the anus), else from the vertex farthest from vertex 0.
/// 2. With g1 the distance from the other end (second open loop, else the
///    farthest vertex), vertices are binned by u = g / (g + g1), whose level
///    sets lie close to cross-sections, into slices ~two mean edges thick;
///    the slice centroids (vertex means: an area-weighted centroid of a bent
///    tube lies kappa r^2 / 2 outside the axis; vertex means assume the wall is
///    sampled evenly around the circumference), between the centroids of the open
///    end loops, give a first polyline, smoothed (Laplacian, ends fixed).
/// 3. Three times: every vertex is re-binned by the arc length of its nearest point
///    on the current polyline (slices perpendicular to the axis, which removes
///    the skew of geodesic slices in bends) and the centroids recomputed.
/// 4. Resampled by arc length (~1 mm), rotation-minimising frames; radius =
///    mean distance of the slice's vertices from the axis. Segment labels are
///    assigned in proportion to the default segment lengths (an assumption:
///    an imported surface carries no anatomical labels).

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/TriangleMesh.h"

namespace colonosim::geometry {

[[nodiscard]] Centreline computeCentreline(const TriangleMesh& mesh);

}  // namespace colonosim::geometry
