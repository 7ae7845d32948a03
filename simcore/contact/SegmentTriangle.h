#pragma once
/// \file
/// Narrow phase between a capsule's axis segment [p0, p1] and a wall triangle
/// (a, b, c), counter-clockwise seen from its outward normal (out of the
/// lumen, geometry/TriangleMesh.h).
///
/// Model: the signed distance d from the wall to the axis is measured along
/// the triangle's inward normal n = -(b - a) x (c - a) / |...| (into the
/// lumen). Where the segment lies over the face (inside the prism over the
/// triangle) d(t) = (p(t) - a) . n is linear in t and its minimum over the
/// part inside the prism is taken at an end of that part, or at its middle
/// when d is constant (segment parallel to the face). Over the edge and
/// vertex regions d is the Euclidean distance between the segment and each
/// edge (closest points of two segments, Ericson, Real-Time Collision
/// Detection, 2005, §5.1.9), counted only when the axis is on the lumen side.
/// The result is the smallest candidate: the deepest axis point. A capsule of
/// radius r touches the wall when d < r; depth = r - d (d < 0: the axis has
/// passed through the wall). A degenerate triangle (no normal) is treated as
/// its three edges with d the unsigned distance. With `maxDistance`, a
/// segment whose both ends lie at least that far on the lumen side of the
/// plane is rejected early (found = false).

#include <Eigen/Core>

#include <limits>

namespace colonosim::contact {

enum class FeatureRegion { Face, Edge, Vertex };

struct SegmentTriangleProximity {
    bool found = false;           ///< false when no candidate lies on the lumen side
    double signedDistance = 0.0;  ///< wall to axis along `normal`, m
    double segmentParam = 0.0;    ///< axis point = p0 + t (p1 - p0), t in [0, 1]
    Eigen::Vector3d axisPoint = Eigen::Vector3d::Zero();
    Eigen::Vector3d wallPoint = Eigen::Vector3d::Zero();
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  ///< of wallPoint on (a, b, c)
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();       ///< unit, from the wall into the lumen
    FeatureRegion region = FeatureRegion::Face;
};

[[nodiscard]] SegmentTriangleProximity
segmentTriangleProximity(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         double maxDistance = std::numeric_limits<double>::infinity());

/// Closest points of segments [p0, p1] and [q0, q1] (robust when either is a
/// point or they are parallel): s and u are the parameters on each.
struct SegmentSegmentClosest {
    double s = 0.0;
    double u = 0.0;
    double squaredDistance = 0.0;
};
[[nodiscard]] SegmentSegmentClosest closestSegmentSegment(const Eigen::Vector3d& p0,
                                                          const Eigen::Vector3d& p1,
                                                          const Eigen::Vector3d& q0,
                                                          const Eigen::Vector3d& q1);

/// Continuous detection: a point moving from p0 to p1 passes through the
/// triangle from the lumen side (d(p0) >= 0) to the outside (d(p1) < 0).
/// `barycentricTolerance` widens the triangle so that a crossing exactly on
/// a shared edge is found by both neighbours.
struct WallCrossing {
    bool crossed = false;
    double t = 0.0;  ///< crossing point = p0 + t (p1 - p0)
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit, into the lumen
};
[[nodiscard]] WallCrossing pointCrossesTriangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                const Eigen::Vector3d& c, double barycentricTolerance = 1e-9);

/// Barycentric coordinates of `p` projected on the plane of (a, b, c).
[[nodiscard]] Eigen::Vector3d barycentricOf(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace colonosim::contact
