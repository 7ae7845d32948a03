#include "simcore/render/ResidualFluid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colonosim::render {

namespace {
/// Below this sine of the tangent's angle to the vertical a ring counts as
/// horizontal (it fills at once when the level passes its centre).
constexpr double kMinSine = 1e-3;

struct Ring {
    double lowest = 0.0;  ///< height of its lowest point, m
    double sine = 1.0;    ///< sin(phi)
    double radius = 0.0;  ///< m
    double length = 0.0;  ///< arc length it stands for, m
};

double volumeBelow(const std::vector<Ring>& rings, double level)
{
    double volume = 0.0;
    for (const Ring& ring : rings) {
        volume += circularSegmentArea(ring.radius, (level - ring.lowest) / ring.sine) * ring.length;
    }
    return volume;
}

bool inPool(const FluidPool& pool, geometry::Segment segment)
{
    return std::find(pool.segments.begin(), pool.segments.end(), segment) != pool.segments.end();
}
}  // namespace

double circularSegmentArea(double radius, double depth)
{
    const double d = std::clamp(depth, 0.0, 2.0 * radius);
    return radius * radius * std::acos(1.0 - d / radius) - (radius - d) * std::sqrt(2.0 * radius * d - d * d);
}

double poolLevel(const geometry::Centreline& centreline, const FluidPool& pool, const Eigen::Vector3d& up)
{
    const int n = centreline.numPoints();
    std::vector<Ring> rings;
    for (int k = 0; k < n; ++k) {
        const auto ku = static_cast<size_t>(k);
        if (!inPool(pool, centreline.segment[ku])) {
            continue;
        }
        const Eigen::Vector3d& t = centreline.tangents[ku];
        const double sine = std::max((up - up.dot(t) * t).norm(), kMinSine);
        const double before = k > 0 ? centreline.arcLength[ku] - centreline.arcLength[ku - 1] : 0.0;
        const double after = k + 1 < n ? centreline.arcLength[ku + 1] - centreline.arcLength[ku] : 0.0;
        const double r = centreline.radius[ku];
        rings.push_back({centreline.points[ku].dot(up) - r * sine, sine, r, (before + after) / 2.0});
    }
    if (rings.empty() || !(pool.volume > 0.0)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    double lo = std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::lowest();
    for (const Ring& ring : rings) {
        lo = std::min(lo, ring.lowest);
        hi = std::max(hi, ring.lowest + 2.0 * ring.radius * ring.sine);
    }
    if (volumeBelow(rings, hi) <= pool.volume) {
        return hi;  // more liquid than lumen: the stretch is full
    }
    // Bisection: 60 halvings take a metre-sized bracket below 1e-15 m.
    for (int i = 0; i < 60; ++i) {
        const double mid = (lo + hi) / 2.0;
        (volumeBelow(rings, mid) < pool.volume ? lo : hi) = mid;
    }
    return (lo + hi) / 2.0;
}

std::vector<float> fluidDepths(const Eigen::Matrix3Xd& restVertices, const std::vector<int>& nearestSamples,
                               const geometry::Centreline& centreline, const std::vector<FluidPool>& pools,
                               const Eigen::Vector3d& down)
{
    const Eigen::Vector3d up = -down.normalized();
    std::vector<double> levels;
    for (const FluidPool& pool : pools) {
        levels.push_back(poolLevel(centreline, pool, up));
    }
    std::vector<float> depth(static_cast<size_t>(restVertices.cols()), kDryDepth);
    for (Eigen::Index i = 0; i < restVertices.cols(); ++i) {
        const auto iu = static_cast<size_t>(i);
        const geometry::Segment segment = centreline.segment[static_cast<size_t>(nearestSamples[iu])];
        for (size_t p = 0; p < pools.size(); ++p) {
            if (std::isfinite(levels[p]) && inPool(pools[p], segment)) {
                depth[iu] = static_cast<float>(levels[p] - restVertices.col(i).dot(up));
                break;
            }
        }
    }
    return depth;
}

}  // namespace colonosim::render
