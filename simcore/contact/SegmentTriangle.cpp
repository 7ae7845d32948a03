#include "simcore/contact/SegmentTriangle.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace colonosim::contact {

namespace {
/// Below this change of d along the clipped segment (m) it counts as parallel to the face.
constexpr double kParallelTolerance = 1e-9;
/// Edge parameters closer than this to an end count as the vertex region.
constexpr double kVertexTolerance = 1e-9;
}  // namespace

SegmentSegmentClosest closestSegmentSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                            const Eigen::Vector3d& q0, const Eigen::Vector3d& q1)
{
    // Ericson, Real-Time Collision Detection, 2005, §5.1.9.
    const Eigen::Vector3d d1 = p1 - p0;
    const Eigen::Vector3d d2 = q1 - q0;
    const Eigen::Vector3d r = p0 - q0;
    const double a = d1.squaredNorm();
    const double e = d2.squaredNorm();
    const double f = d2.dot(r);
    constexpr double eps = 1e-24;
    double s = 0.0;
    double u = 0.0;
    if (a <= eps && e <= eps) {
        s = u = 0.0;
    } else if (a <= eps) {
        u = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= eps) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2);
            const double denom = a * e - b * b;
            // Parallel segments (denom 0): any s works; take 0 and let u follow.
            s = denom > eps * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            u = (b * s + f) / e;
            if (u < 0.0) {
                u = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (u > 1.0) {
                u = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    SegmentSegmentClosest result;
    result.s = s;
    result.u = u;
    result.squaredDistance = ((p0 + s * d1) - (q0 + u * d2)).squaredNorm();
    return result;
}

Eigen::Vector3d barycentricOf(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c)
{
    const Eigen::Vector3d v0 = b - a;
    const Eigen::Vector3d v1 = c - a;
    const Eigen::Vector3d v2 = p - a;
    const double d00 = v0.dot(v0);
    const double d01 = v0.dot(v1);
    const double d11 = v1.dot(v1);
    const double d20 = v2.dot(v0);
    const double d21 = v2.dot(v1);
    const double denom = d00 * d11 - d01 * d01;
    if (denom <= 0.0) {
        return Eigen::Vector3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    }
    const double v = (d11 * d20 - d01 * d21) / denom;
    const double w = (d00 * d21 - d01 * d20) / denom;
    return Eigen::Vector3d(1.0 - v - w, v, w);
}

SegmentTriangleProximity segmentTriangleProximity(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                  const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                  const Eigen::Vector3d& c, double maxDistance)
{
    const std::array<Eigen::Vector3d, 3> v{a, b, c};
    const Eigen::Vector3d outward = (b - a).cross(c - a);
    const double scale2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const bool degenerate = outward.squaredNorm() <= 1e-20 * scale2 * scale2 || scale2 == 0.0;
    const Eigen::Vector3d inward =
        degenerate ? Eigen::Vector3d::Zero() : Eigen::Vector3d(-outward.normalized());
    const Eigen::Vector3d dir = p1 - p0;

    SegmentTriangleProximity best;
    auto offer = [&](double d, double t, const Eigen::Vector3d& wall, const Eigen::Vector3d& bary,
                     const Eigen::Vector3d& normal, FeatureRegion region) {
        if (best.found && d >= best.signedDistance) {
            return;
        }
        best.found = true;
        best.signedDistance = d;
        best.segmentParam = t;
        best.axisPoint = p0 + t * dir;
        best.wallPoint = wall;
        best.barycentric = bary;
        best.normal = normal;
        best.region = region;
    };

    // Edges whose half-space an end of the segment leaves (all of them for a degenerate triangle).
    std::array<bool, 3> outsideEdge{true, true, true};
    if (!degenerate) {
        // Every candidate is at least the smaller plane distance of the two ends.
        if (std::min((p0 - a).dot(inward), (p1 - a).dot(inward)) >= maxDistance) {
            return best;
        }
        // Clip the segment to the prism over the face: (p(t) - v_i) . m_i >= 0 for each edge.
        double lo = 0.0;
        double hi = 1.0;
        for (int i = 0; i < 3; ++i) {
            const Eigen::Vector3d m =
                outward.cross(v[static_cast<size_t>((i + 1) % 3)] - v[static_cast<size_t>(i)]);
            const double alpha = (p0 - v[static_cast<size_t>(i)]).dot(m);
            const double beta = dir.dot(m);
            outsideEdge[static_cast<size_t>(i)] = alpha < 0.0 || alpha + beta < 0.0;
            if (std::abs(beta) <= 1e-30) {
                if (alpha < 0.0) {
                    hi = -1.0;
                }
            } else if (beta > 0.0) {
                lo = std::max(lo, -alpha / beta);
            } else {
                hi = std::min(hi, -alpha / beta);
            }
        }
        if (lo <= hi) {
            const double dLo = (p0 + lo * dir - a).dot(inward);
            const double dHi = (p0 + hi * dir - a).dot(inward);
            const double t =
                std::abs(dHi - dLo) <= kParallelTolerance ? 0.5 * (lo + hi) : (dLo < dHi ? lo : hi);
            const Eigen::Vector3d axis = p0 + t * dir;
            const double d = (axis - a).dot(inward);
            const Eigen::Vector3d wall = axis - d * inward;
            offer(d, t, wall, barycentricOf(wall, a, b, c), inward, FeatureRegion::Face);
        }
    }
    for (int i = 0; i < 3; ++i) {
        // A segment inside an edge's half-space is nearer to the face or to another edge.
        if (!outsideEdge[static_cast<size_t>(i)]) {
            continue;
        }
        const Eigen::Vector3d& q0 = v[static_cast<size_t>(i)];
        const Eigen::Vector3d& q1 = v[static_cast<size_t>((i + 1) % 3)];
        const SegmentSegmentClosest cp = closestSegmentSegment(p0, p1, q0, q1);
        const Eigen::Vector3d axis = p0 + cp.s * dir;
        const Eigen::Vector3d wall = q0 + cp.u * (q1 - q0);
        const Eigen::Vector3d gap = axis - wall;
        if (!degenerate && gap.dot(inward) < 0.0) {
            continue;  // behind the plane outside the prism: a neighbour's face region
        }
        const double dist = std::sqrt(cp.squaredDistance);
        Eigen::Vector3d normal = dist > 1e-12 ? Eigen::Vector3d(gap / dist) : inward;
        if (normal.isZero()) {
            // Degenerate triangle touched by the axis: any direction normal to the segment.
            normal = dir.unitOrthogonal();
        }
        Eigen::Vector3d bary = Eigen::Vector3d::Zero();
        bary[i] = 1.0 - cp.u;
        bary[(i + 1) % 3] = cp.u;
        const bool vertex = cp.u <= kVertexTolerance || cp.u >= 1.0 - kVertexTolerance;
        offer(dist, cp.s, wall, bary, normal, vertex ? FeatureRegion::Vertex : FeatureRegion::Edge);
    }
    return best;
}

WallCrossing pointCrossesTriangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                  const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c, double barycentricTolerance)
{
    WallCrossing result;
    const Eigen::Vector3d outward = (b - a).cross(c - a);
    const double h0 = -(p0 - a).dot(outward);
    const double h1 = -(p1 - a).dot(outward);
    if (!(h0 >= 0.0 && h1 < 0.0)) {
        return result;
    }
    const double t = h0 / (h0 - h1);
    const Eigen::Vector3d q = p0 + t * (p1 - p0);
    const Eigen::Vector3d bary = barycentricOf(q, a, b, c);
    if (bary.minCoeff() < -barycentricTolerance) {
        return result;
    }
    result.crossed = true;
    result.t = t;
    result.point = q;
    result.barycentric = bary;
    result.normal = -outward.normalized();
    return result;
}

}  // namespace colonosim::contact
