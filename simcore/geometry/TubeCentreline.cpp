#include "simcore/geometry/TubeCentreline.h"

#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/SurfaceGraph.h"
#include "simcore/geometry/TubeSections.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace colonosim::geometry {

namespace {

using surface::argmaxFinite;
using surface::boundaryLoops;
using surface::buildGraph;
using surface::EdgeGraph;
using surface::geodesic;
using surface::levelSets;
using surface::Section;

constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Vector3d centroid(const TriangleMesh& mesh, const std::vector<int>& vertices)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : vertices)
        c += mesh.vertices.col(v);
    return c / static_cast<double>(std::max<std::size_t>(1, vertices.size()));
}

double meanDistance(const TriangleMesh& mesh, const std::vector<int>& vertices, const Eigen::Vector3d& c)
{
    double sum = 0.0;
    for (int v : vertices)
        sum += (mesh.vertices.col(v) - c).norm();
    return sum / static_cast<double>(std::max<std::size_t>(1, vertices.size()));
}

std::vector<double> cumulative(const std::vector<Eigen::Vector3d>& p)
{
    std::vector<double> c(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i)
        c[i] = c[i - 1] + (p[i] - p[i - 1]).norm();
    return c;
}

/// Linear interpolation of y(x) at `x` (x ascending; clamped at the ends).
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x)
{
    if (xs.empty())
        return 0.0;
    if (x <= xs.front())
        return ys.front();
    if (x >= xs.back())
        return ys.back();
    const auto i = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
    const double span = xs[i] - xs[i - 1];
    const double u = span > 0.0 ? (x - xs[i - 1]) / span : 0.0;
    return (1.0 - u) * ys[i - 1] + u * ys[i];
}

/// The centreline as it is being refined: points with the radius of the
/// section each came from (the end points take their neighbour's).
struct Axis {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> radius;
};

/// End point of the tube at one end: an open loop's centroid, else a vertex
/// (a cap's apex, or an end of the diameter).
struct End {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double radius = 0.0;
    bool open = false;
};

/// Axis from the sections of `field` (range [0, total]), between the two ends.
/// `levelOf` receives the field value of each axis point.
Axis axisFromSections(const TriangleMesh& mesh, const std::vector<double>& field, double total,
                      double spacing, const End& start, const End& end, std::vector<double>* levelOf)
{
    const int count = std::max(4, static_cast<int>(std::lround(total / spacing)));
    const double step = total / count;
    const std::vector<Section> sections = levelSets(mesh, field, 0.5 * step, step, count);
    Axis axis;
    levelOf->clear();
    axis.points.push_back(start.point);
    axis.radius.push_back(start.radius);
    levelOf->push_back(0.0);
    for (std::size_t k = 0; k < sections.size(); ++k) {
        if (sections[k].contourLength <= 0.0)
            continue;
        axis.points.push_back(sections[k].centre);
        axis.radius.push_back(sections[k].radius);
        levelOf->push_back((static_cast<double>(k) + 0.5) * step);
    }
    axis.points.push_back(end.point);
    axis.radius.push_back(end.radius);
    levelOf->push_back(total);
    if (!start.open && axis.radius.size() > 2)
        axis.radius.front() = axis.radius[1];
    if (!end.open && axis.radius.size() > 2)
        axis.radius.back() = axis.radius[axis.radius.size() - 2];
    // Light smoothing (ends fixed): the sections are already smooth.
    std::vector<Eigen::Vector3d> q = axis.points;
    for (std::size_t i = 1; i + 1 < q.size(); ++i)
        q[i] = 0.25 * axis.points[i - 1] + 0.5 * axis.points[i] + 0.25 * axis.points[i + 1];
    axis.points = q;
    return axis;
}

/// Arc length of each vertex's nearest point on the axis, searched only
/// within +-window(s) of its current estimate `s` (a topological
/// neighbourhood: parts of the tube that are close in space but far along
/// the tube are never candidates). Replaces `s`.
void projectLocally(const TriangleMesh& mesh, const Axis& axis, std::vector<double>& s)
{
    const std::vector<double> cum = cumulative(axis.points);
    for (std::size_t v = 0; v < s.size(); ++v) {
        if (!std::isfinite(s[v]))
            continue;
        const Eigen::Vector3d p = mesh.vertices.col(static_cast<Eigen::Index>(v));
        const double r = interpolate(cum, axis.radius, s[v]);
        const double window =
            3.0 * r + 2.0 * (cum.back() / static_cast<double>(std::max<std::size_t>(1, cum.size() - 1)));
        const auto lo = static_cast<std::size_t>(std::max<std::ptrdiff_t>(
            0, (std::lower_bound(cum.begin(), cum.end(), s[v] - window) - cum.begin()) - 1));
        const auto hi = std::min(
            cum.size() - 1,
            static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), s[v] + window) - cum.begin()));
        double best = kInf;
        double bestS = s[v];
        for (std::size_t i = lo; i < hi; ++i) {
            const Eigen::Vector3d d = axis.points[i + 1] - axis.points[i];
            const double len2 = d.squaredNorm();
            // Beyond the first and last points the axis is extended straight,
            // so that the end loops' vertices get s <= 0 and s >= length.
            const double lower = i == 0 ? -kInf : 0.0;
            const double upper = i + 2 == cum.size() ? kInf : 1.0;
            const double u = len2 > 0.0 ? std::clamp((p - axis.points[i]).dot(d) / len2, lower, upper) : 0.0;
            const double dist = (axis.points[i] + u * d - p).squaredNorm();
            if (dist < best) {
                best = dist;
                bestS = cum[i] + u * (cum[i + 1] - cum[i]);
            }
        }
        s[v] = bestS;
    }
}

/// Largest section radius over the last stretch of a closed end: scanning
/// from the end, until the stretch is three such radii long.
double tubeRadiusNearEnd(const std::vector<double>& fromEnd, const std::vector<double>& radius)
{
    double peak = 0.0;
    for (std::size_t i = 0; i < fromEnd.size(); ++i) {
        peak = std::max(peak, radius[i]);
        if (i > 2 && fromEnd[i] > 3.0 * peak)
            break;
    }
    return peak;
}

/// Arc length at which a closed end's cap begins, measured from that end
/// (0 for an open end). Sections on a cap shrink towards its apex; the cap
/// starts where the section radius falls below 90% of the tube's radius just
/// before it (the largest over the last three radii of the tube).
double capLength(const std::vector<double>& fromEnd, const std::vector<double>& radius)
{
    const double threshold = 0.9 * tubeRadiusNearEnd(fromEnd, radius);
    for (std::size_t k = 0; k < fromEnd.size(); ++k) {
        if (radius[k] >= threshold) {
            if (k == 0)
                return 0.0;
            const double u = (threshold - radius[k - 1]) / (radius[k] - radius[k - 1]);
            return fromEnd[k - 1] + std::clamp(u, 0.0, 1.0) * (fromEnd[k] - fromEnd[k - 1]);
        }
    }
    return 0.0;
}

/// The apex of a closed end: of the vertices within two tube radii of the
/// end (by their slice coordinate `s`, so topologically), the one farthest
/// along the axis direction there. The farthest vertex by geodesic distance
/// is usually on the rim of the cap (the outer wall of the last bend is
/// longer), which would pull the end of the axis sideways.
int capApex(const TriangleMesh& mesh, const Axis& axis, const std::vector<double>& s, bool atEnd)
{
    std::vector<double> cum = cumulative(axis.points);
    const double length = cum.back();
    std::vector<double> fromEnd, radius;
    std::vector<Eigen::Vector3d> points;
    for (std::size_t k = 0; k < cum.size(); ++k) {
        const std::size_t i = atEnd ? cum.size() - 1 - k : k;
        fromEnd.push_back(atEnd ? length - cum[i] : cum[i]);
        radius.push_back(axis.radius[i]);
        points.push_back(axis.points[i]);
    }
    const double r = tubeRadiusNearEnd(fromEnd, radius);
    const auto at = [&](double d) {
        const auto i = static_cast<std::size_t>(
            std::clamp<std::ptrdiff_t>(std::upper_bound(fromEnd.begin(), fromEnd.end(), d) - fromEnd.begin(),
                                       1, static_cast<std::ptrdiff_t>(fromEnd.size()) - 1));
        const double span = fromEnd[i] - fromEnd[i - 1];
        const double u = span > 0.0 ? std::clamp((d - fromEnd[i - 1]) / span, 0.0, 1.0) : 0.0;
        return Eigen::Vector3d((1.0 - u) * points[i - 1] + u * points[i]);
    };
    const Eigen::Vector3d base = at(r);
    const Eigen::Vector3d direction = (base - at(3.0 * r)).normalized();
    int best = -1;
    double farthest = -kInf;
    for (std::size_t v = 0; v < s.size(); ++v) {
        if (!std::isfinite(s[v]))
            continue;
        if ((atEnd ? length - s[v] : s[v]) > 2.0 * r)
            continue;
        const double along = (mesh.vertices.col(static_cast<Eigen::Index>(v)) - base).dot(direction);
        if (along > farthest) {
            farthest = along;
            best = static_cast<int>(v);
        }
    }
    return best;
}

}  // namespace

Centreline computeCentreline(const TriangleMesh& mesh)
{
    const auto numV = static_cast<std::size_t>(mesh.numVertices());
    const EdgeGraph graph = buildGraph(mesh);
    const auto loops = boundaryLoops(graph, numV);

    // 1. Geodesic distance from one end (the longest open loop: the anus;
    //    without an open loop, one end of the diameter of two sweeps), and
    //    from the other end (the second loop, else the farthest vertex).
    End start, end;
    std::vector<int> sources;
    if (!loops.empty()) {
        sources = loops.front();
        start.point = centroid(mesh, sources);
        start.radius = meanDistance(mesh, sources, start.point);
        start.open = true;
    } else {
        sources = {argmaxFinite(geodesic(graph, {0}))};
        start.point = mesh.vertices.col(sources.front());
    }
    std::vector<int> farSources;
    if (loops.size() > 1) {
        farSources = loops[1];
        end.point = centroid(mesh, farSources);
        end.radius = meanDistance(mesh, farSources, end.point);
        end.open = true;
    }

    // 2. Topological slices: level sets of u = g0 / (g0 + g1) (times the
    //    length), with g1 the geodesic distance from the other end. A level
    //    set is one ring of the tube however close other loops of the colon
    //    come in space, and u = 0 and 1 exactly on the end loops.
    const double spacing = std::max(graph.meanEdge, 1e-9);
    std::vector<double> s(numV, kInf);
    std::vector<double> levelOf;
    Axis axis;
    const auto slice = [&] {
        const std::vector<double> g0 = geodesic(graph, sources);
        if (farSources.empty()) {
            farSources = {argmaxFinite(g0)};
            end.point = mesh.vertices.col(farSources.front());
        }
        const std::vector<double> g1 = geodesic(graph, farSources);
        double total = 0.0;
        for (int v : farSources)
            total += g0[static_cast<std::size_t>(v)];
        total /= static_cast<double>(farSources.size());
        for (std::size_t v = 0; v < numV; ++v) {
            const double sum = g0[v] + g1[v];
            s[v] = std::isfinite(sum) ? (sum > 0.0 ? total * g0[v] / sum : 0.0) : kInf;
        }
        axis = axisFromSections(mesh, s, total, spacing, start, end, &levelOf);
        // From level to arc length along the axis.
        const std::vector<double> cum = cumulative(axis.points);
        for (double& sv : s) {
            if (std::isfinite(sv))
                sv = interpolate(levelOf, cum, sv);
        }
    };
    slice();
    // A closed end starts from the apex of its cap, then the slices again.
    if (!end.open || !start.open) {
        if (!end.open) {
            const int apex = capApex(mesh, axis, s, true);
            if (apex >= 0) {
                farSources = {apex};
                end.point = mesh.vertices.col(apex);
            }
        }
        if (!start.open) {
            const int apex = capApex(mesh, axis, s, false);
            if (apex >= 0) {
                sources = {apex};
                start.point = mesh.vertices.col(apex);
            }
        }
        slice();
    }

    // 3. Perpendicular slices: each vertex takes the arc length of its nearest
    //    axis point, searched only near its own slice; sections of that field
    //    are perpendicular to the axis, which removes the skew of geodesic
    //    level sets in bends. Twice.
    for (int refinement = 0; refinement < 2; ++refinement) {
        projectLocally(mesh, axis, s);
        const double length = cumulative(axis.points).back();
        axis = axisFromSections(mesh, s, length, spacing, start, end, &levelOf);
    }

    // 4. Closed ends: cut off the cap, where the sections shrink to its apex.
    std::vector<double> cum = cumulative(axis.points);
    double from = 0.0;
    double to = cum.back();
    if (!end.open) {
        std::vector<double> fromEnd, radius;
        for (std::size_t i = axis.points.size() - 1; i-- > 0;) {
            fromEnd.push_back(cum.back() - cum[i]);
            radius.push_back(axis.radius[i]);
        }
        to -= capLength(fromEnd, radius);
    }
    if (!start.open) {
        const std::vector<double> fromStart(cum.begin() + 1, cum.end());
        const std::vector<double> radius(axis.radius.begin() + 1, axis.radius.end());
        from += capLength(fromStart, radius);
    }
    if (to <= from) {
        from = 0.0;
        to = cum.back();
    }
    std::vector<Eigen::Vector3d> polyline;
    std::vector<double> polylineS, polylineR;
    const auto pointAt = [&](double at) {
        const auto i = static_cast<std::size_t>(
            std::clamp<std::ptrdiff_t>(std::upper_bound(cum.begin(), cum.end(), at) - cum.begin(), 1,
                                       static_cast<std::ptrdiff_t>(cum.size()) - 1));
        const double span = cum[i] - cum[i - 1];
        const double u = span > 0.0 ? std::clamp((at - cum[i - 1]) / span, 0.0, 1.0) : 0.0;
        return Eigen::Vector3d((1.0 - u) * axis.points[i - 1] + u * axis.points[i]);
    };
    polyline.push_back(pointAt(from));
    for (std::size_t i = 0; i < axis.points.size(); ++i) {
        if (cum[i] > from && cum[i] < to)
            polyline.push_back(axis.points[i]);
    }
    polyline.push_back(pointAt(to));
    for (std::size_t i = 0; i < axis.points.size(); ++i) {
        polylineS.push_back(cum[i] - from);
        polylineR.push_back(axis.radius[i]);
    }

    // 5. Resampled by arc length (~1 mm), frames, radius from the sections.
    Centreline c;
    const double length = cumulative(polyline).back();
    c.points = resampleByArcLength(polyline, std::max(2, static_cast<int>(std::ceil(length / 0.001)) + 1));
    computeArcLengthAndFrames(c, -Eigen::Vector3d::UnitY());
    c.radius.resize(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i)
        c.radius[i] = interpolate(polylineS, polylineR, c.arcLength[i]);

    const AnatomyParameters defaults;
    c.segment.resize(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        double boundary = 0.0;
        int seg = 0;
        for (; seg + 1 < kNumSegments; ++seg) {
            boundary += defaults.length(static_cast<Segment>(seg)) / defaults.totalLength() * length;
            if (c.arcLength[i] < boundary)
                break;
        }
        c.segment[i] = static_cast<Segment>(seg);
    }
    return c;
}

}  // namespace colonosim::geometry
