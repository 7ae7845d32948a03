#pragma once
/// \file
/// Centreline of an arbitrary tube-shaped surface (an imported colon),
/// found topologically, so that loops of the tube that come close in space
/// (sigmoid loop, sagging transverse colon) are never mixed up.
///
/// 1. Ends: the longest open boundary loop (the anus) and the second one if
///    any; without one, an end of the diameter found by two Dijkstra sweeps.
/// 2. Geodesic distances g0, g1 from both ends (Dijkstra over the mesh edges,
///    weighted by length, O(E log V)). Slices are level sets of
///    u = L g0 / (g0 + g1): each is one ring of the tube, because distance is
///    measured along the surface, and u is exactly 0 and L on the end loops.
///    The level sets are extracted as iso-contours (marching triangles, so
///    independent of the mesh resolution); a slice's centre is the
///    length-weighted centroid of its contour, its radius the mean distance of
///    the contour from the centre. Centres between the end points, smoothed
///    once (ends fixed), give the first axis.
/// 3. A closed end (cecal cap): its apex is re-chosen as the vertex near that
///    end (by slice) farthest along the axis (the farthest vertex by geodesic
///    distance lies on the rim of the cap) and step 2 is repeated from it.
/// 4. Twice: each vertex takes the arc length of its nearest point on the axis,
///    searched only within 3 local radii of its own slice (a topological
///    window, never another loop), and the axis is rebuilt from the
///    iso-contours of that field: cross-sections perpendicular to the axis,
///    which removes the skew of geodesic level sets in bends.
/// 5. A closed end is cut where the slices shrink onto the cap (radius below
///    90% of the tube's just before it). Resampled by arc length (~1 mm),
///    rotation-minimising frames, radius interpolated from the slices.
///    Segment labels are assigned in proportion to the default segment
///    lengths (an assumption: an imported surface carries no labels).
///
/// Cost: a few Dijkstra sweeps and contour passes; about 0.1 s for the
/// 110,000-face visual mesh of the default colon.

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/TriangleMesh.h"

namespace colonosim::geometry {

[[nodiscard]] Centreline computeCentreline(const TriangleMesh& mesh);

}  // namespace colonosim::geometry
