#include "simcore/geometry/CentrelineSampling.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace colonosim::geometry {

namespace {

Eigen::Vector3d anyPerpendicular(const Eigen::Vector3d& t)
{
    const Eigen::Vector3d axis = std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return t.cross(axis).normalized();
}

Eigen::Vector3d orthogonalTo(const Eigen::Vector3d& v, const Eigen::Vector3d& t)
{
    const Eigen::Vector3d projected = v - v.dot(t) * t;
    const double norm = projected.norm();
    return norm > 1e-9 ? Eigen::Vector3d(projected / norm) : anyPerpendicular(t);
}

}  // namespace

std::vector<Eigen::Vector3d> resampleByArcLength(const std::vector<Eigen::Vector3d>& polyline, int numSamples)
{
    std::vector<double> cumulative(polyline.size(), 0.0);
    for (std::size_t i = 1; i < polyline.size(); ++i) {
        cumulative[i] = cumulative[i - 1] + (polyline[i] - polyline[i - 1]).norm();
    }
    std::vector<Eigen::Vector3d> out;
    out.reserve(static_cast<std::size_t>(numSamples));
    const double total = cumulative.empty() ? 0.0 : cumulative.back();
    std::size_t k = 0;
    for (int i = 0; i < numSamples; ++i) {
        const double s = numSamples > 1 ? total * i / (numSamples - 1) : 0.0;
        while (k + 2 < polyline.size() && cumulative[k + 1] < s) {
            ++k;
        }
        const double span = cumulative[k + 1] - cumulative[k];
        const double u = span > 0.0 ? std::clamp((s - cumulative[k]) / span, 0.0, 1.0) : 0.0;
        out.push_back((1.0 - u) * polyline[k] + u * polyline[k + 1]);
    }
    return out;
}

void computeArcLengthAndFrames(Centreline& c, const Eigen::Vector3d& firstNormalHint)
{
    const std::size_t n = c.points.size();
    c.arcLength.assign(n, 0.0);
    c.tangents.assign(n, Eigen::Vector3d::UnitZ());
    c.normals.assign(n, Eigen::Vector3d::UnitX());
    if (n < 2) {
        return;
    }
    for (std::size_t i = 1; i < n; ++i) {
        c.arcLength[i] = c.arcLength[i - 1] + (c.points[i] - c.points[i - 1]).norm();
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = i == 0 ? 0 : i - 1;
        const std::size_t b = i + 1 == n ? n - 1 : i + 1;
        c.tangents[i] = (c.points[b] - c.points[a]).normalized();
    }
    c.normals[0] = orthogonalTo(firstNormalHint, c.tangents[0]);
    // Double reflection (Wang et al. 2008).
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const Eigen::Vector3d v1 = c.points[i + 1] - c.points[i];
        const double c1 = v1.squaredNorm();
        if (c1 < 1e-30) {
            c.normals[i + 1] = orthogonalTo(c.normals[i], c.tangents[i + 1]);
            continue;
        }
        const Eigen::Vector3d rL = c.normals[i] - (2.0 / c1) * v1.dot(c.normals[i]) * v1;
        const Eigen::Vector3d tL = c.tangents[i] - (2.0 / c1) * v1.dot(c.tangents[i]) * v1;
        const Eigen::Vector3d v2 = c.tangents[i + 1] - tL;
        const double c2 = v2.squaredNorm();
        const Eigen::Vector3d r = c2 < 1e-30 ? rL : Eigen::Vector3d(rL - (2.0 / c2) * v2.dot(rL) * v2);
        c.normals[i + 1] = orthogonalTo(r, c.tangents[i + 1]);
    }
}

CentrelineSample sampleCentreline(const Centreline& c, double s)
{
    CentrelineSample out;
    const int n = c.numPoints();
    if (n == 0) {
        return out;
    }
    s = std::clamp(s, 0.0, c.length());
    const auto it = std::upper_bound(c.arcLength.begin(), c.arcLength.end(), s);
    const int k = std::clamp(static_cast<int>(it - c.arcLength.begin()) - 1, 0, std::max(0, n - 2));
    const int k1 = std::min(k + 1, n - 1);
    const double span = c.arcLength[static_cast<std::size_t>(k1)] - c.arcLength[static_cast<std::size_t>(k)];
    const double u =
        span > 0.0 ? std::clamp((s - c.arcLength[static_cast<std::size_t>(k)]) / span, 0.0, 1.0) : 0.0;
    const auto lerp = [u](const auto& a, const auto& b) { return (1.0 - u) * a + u * b; };
    const auto sk = static_cast<std::size_t>(k);
    const auto sk1 = static_cast<std::size_t>(k1);
    out.point = lerp(c.points[sk], c.points[sk1]);
    out.tangent = lerp(c.tangents[sk], c.tangents[sk1]).normalized();
    out.normal = orthogonalTo(lerp(c.normals[sk], c.normals[sk1]), out.tangent);
    out.binormal = out.tangent.cross(out.normal);
    out.radius = c.radius.empty() ? 0.0 : lerp(c.radius[sk], c.radius[sk1]);
    out.segment = c.segment.empty() ? Segment::Rectum : c.segment[u < 0.5 ? sk : sk1];
    return out;
}

}  // namespace colonosim::geometry
