#pragma once
/// \file
/// Residual fluid of the bowel preparation: where it lies on the wall.
///
/// Model: liquid finds its level. A pool of volume V spread over a stretch
/// of colon (the segments of one bowel region) comes to rest with a flat,
/// horizontal surface at the height H (along "up", against gravity) at which
/// the lumen below H holds V:
///   V(H) = sum_k A(r_k, d_k(H)) ds_k,  d_k(H) = clamp((H - l_k) / sin(phi_k), 0, 2 r_k),
/// over the centreline samples k of the stretch (ds_k the arc length each
/// sample stands for, r_k the lumen radius), where
///   l_k = c_k.up - r_k sin(phi_k)  is the height of the ring's lowest point,
///   sin(phi_k) = |up - (up.t_k) t_k|, phi_k the tangent's angle to the vertical
///     (the depth of a cut of the tilted ring, measured in its plane, is the
///     height over sin(phi_k); a vertical stretch fills ring by ring),
///   A(r, d) = r^2 acos(1 - d / r) - (r - d) sqrt(2 r d - d^2)  the area of a
///     circular segment of depth d (0 at d = 0, pi r^2 / 2 at d = r).
/// V(H) is monotone in H and is solved by bisection. The pool thus gathers in
/// the dependent parts of the stretch (a sagging transverse colon, the
/// descending colon of a patient in left lateral decubitus) and its surface
/// is one plane, as a liquid's is; a volume beyond the stretch's lumen fills
/// it. A wall vertex is under the pool when its rest height is below H, by
/// H - v.up (m). Limits: the rest geometry stands for the lumen (the wall's
/// sag under gravity and the scope's push do not move the level), and a pool
/// ends at its stretch's ends (neighbouring regions keep their own levels).

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/Segment.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::render {

/// A volume of liquid (m^3) free to flow within `segments`.
struct FluidPool {
    std::vector<geometry::Segment> segments;
    double volume = 0.0;  ///< m^3
};

/// Area of the circular segment of depth `depth` (clamped to [0, 2 r]) of a
/// circle of radius `radius`, m^2.
[[nodiscard]] double circularSegmentArea(double radius, double depth);

/// The height H of `pool`'s surface along `up` (unit), m, on `centreline`
/// (model above); NaN when the pool is empty or none of its segments is on
/// the centreline.
[[nodiscard]] double poolLevel(const geometry::Centreline& centreline, const FluidPool& pool,
                               const Eigen::Vector3d& up);

/// Depth of each vertex below its pool's surface, m (negative above it, and
/// kDryDepth where no pool lies), from the vertex's nearest centreline sample.
[[nodiscard]] std::vector<float> fluidDepths(const Eigen::Matrix3Xd& restVertices,
                                             const std::vector<int>& nearestSamples,
                                             const geometry::Centreline& centreline,
                                             const std::vector<FluidPool>& pools,
                                             const Eigen::Vector3d& down);

/// The depth given to vertices of stretches without fluid, m.
inline constexpr float kDryDepth = -1.0F;

}  // namespace colonosim::render
