#include "simcore/render/WallSurface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace colonosim::render {

namespace {
int sampleAt(const geometry::Centreline& centreline, double arcLength)
{
    const auto it = std::lower_bound(centreline.arcLength.begin(), centreline.arcLength.end(), arcLength);
    const int k = static_cast<int>(it - centreline.arcLength.begin());
    return std::clamp(k, 0, centreline.numPoints() - 1);
}

int nearestSample(const geometry::Centreline& centreline, const Eigen::Vector3d& p)
{
    int best = 0;
    double bestDistance = std::numeric_limits<double>::max();
    for (int k = 0; k < centreline.numPoints(); ++k) {
        const double d = (centreline.points[static_cast<size_t>(k)] - p).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}

/// The chart's place of `p` measured from centreline sample `k`: the arc
/// length continued along the sample's tangent (so that it is continuous
/// between samples) and the clock angle in its frame.
WallPlace placeFromSample(const geometry::Centreline& centreline, int k, const Eigen::Vector3d& p)
{
    const auto ks = static_cast<size_t>(k);
    const Eigen::Vector3d offset = p - centreline.points[ks];
    const Eigen::Vector3d& normal = centreline.normals[ks];
    const Eigen::Vector3d binormal = centreline.tangents[ks].cross(normal);
    return {centreline.arcLength[ks] + offset.dot(centreline.tangents[ks]),
            std::atan2(offset.dot(binormal), offset.dot(normal))};
}

/// Inward relief (m, positive towards the centreline) and colour weight of a
/// lesion at wall distance d.
std::pair<double, double> lesionRelief(const Lesion& lesion, double d)
{
    const double radius = lesion.diameter / 2.0;
    if (d >= radius) {
        return {0.0, 0.0};
    }
    const double q = 1.0 - (d / radius) * (d / radius);
    const double weight = std::clamp((1.0 - d / radius) / 0.2, 0.0, 1.0);
    switch (lesion.shape) {
    case LesionShape::Pedunculated: return {1.2 * lesion.diameter * std::pow(q, 0.35), weight};
    case LesionShape::Sessile: return {0.5 * lesion.diameter * std::sqrt(q), weight};
    case LesionShape::Flat: return {1.5e-3 * q, weight};
    case LesionShape::Depressed: return {-1.0e-3 * q, weight};
    }
    return {0.0, 0.0};
}
}  // namespace

Eigen::Vector3d wallPoint(const geometry::Centreline& centreline, const WallPlace& place)
{
    const auto k = static_cast<size_t>(sampleAt(centreline, place.arcLength));
    const Eigen::Vector3d& n = centreline.normals[k];
    const Eigen::Vector3d b = centreline.tangents[k].cross(n);
    return centreline.points[k] +
           centreline.radius[k] * (std::cos(place.angle) * n + std::sin(place.angle) * b);
}

WallPlace wallPlaceAt(const geometry::Centreline& centreline, const Eigen::Vector3d& p)
{
    return placeFromSample(centreline, nearestSample(centreline, p), p);
}

WallSurface buildWallSurface(const geometry::TriangleMesh& visualRest, const geometry::Centreline& centreline,
                             const WallFindings& findings)
{
    if (centreline.numPoints() < 2) {
        throw std::invalid_argument("buildWallSurface: the centreline needs at least two samples");
    }
    WallSurface surface;
    surface.rest = visualRest;
    const int n = visualRest.numVertices();
    surface.chart.resize(static_cast<size_t>(n) * 3);
    surface.finding.assign(static_cast<size_t>(n) * 4, 0.0F);
    surface.vertexSegment.resize(static_cast<size_t>(n));

    std::vector<Eigen::Vector3d> lesionCentres;
    for (const Lesion& lesion : findings.lesions) {
        lesionCentres.push_back(wallPoint(centreline, lesion.place));
    }
    std::vector<Eigen::Vector3d> pocketCentres;
    for (const Diverticulum& pocket : findings.diverticula) {
        pocketCentres.push_back(wallPoint(centreline, pocket.place));
    }
    surface.lesionTops = lesionCentres;
    std::vector<double> lesionTopHeight(findings.lesions.size(), -1.0);

    // Nearest samples of consecutive vertices are close: search a window
    // around the previous one first, and the whole centreline when the
    // window's best lies on its edge.
    int previous = 0;
    constexpr int kWindow = 40;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d v = visualRest.vertices.col(i);
        const int from = std::max(0, previous - kWindow);
        const int to = std::min(centreline.numPoints() - 1, previous + kWindow);
        int k = from;
        double best = std::numeric_limits<double>::max();
        for (int j = from; j <= to; ++j) {
            const double d = (centreline.points[static_cast<size_t>(j)] - v).squaredNorm();
            if (d < best) {
                best = d;
                k = j;
            }
        }
        if ((k == from && from > 0) || (k == to && to < centreline.numPoints() - 1)) {
            k = nearestSample(centreline, v);
        }
        previous = k;
        const auto ks = static_cast<size_t>(k);
        const WallPlace at = placeFromSample(centreline, k, v);
        const auto iu = static_cast<size_t>(i);
        surface.chart[3 * iu] = static_cast<float>(at.arcLength);
        surface.chart[3 * iu + 1] = static_cast<float>(centreline.radius[ks] * std::cos(at.angle));
        surface.chart[3 * iu + 2] = static_cast<float>(centreline.radius[ks] * std::sin(at.angle));
        surface.vertexSegment[iu] = centreline.segment[ks];
        surface.finding[4 * iu + 2] =
            static_cast<float>(findings.stoolFraction[static_cast<size_t>(centreline.segment[ks])]);

        // Radial direction, outwards; relief moves the vertex against it.
        const Eigen::Vector3d offset = v - centreline.points[ks];
        const Eigen::Vector3d radial =
            (offset - offset.dot(centreline.tangents[ks]) * centreline.tangents[ks]).normalized();
        double relief = 0.0;
        for (size_t l = 0; l < findings.lesions.size(); ++l) {
            const auto [h, weight] = lesionRelief(findings.lesions[l], (v - lesionCentres[l]).norm());
            if (weight > surface.finding[4 * iu]) {
                surface.finding[4 * iu] = static_cast<float>(weight);
                surface.finding[4 * iu + 1] = static_cast<float>(findings.lesions[l].tissue);
            }
            relief += h;
            if (weight > 0.0 && h > lesionTopHeight[l]) {
                lesionTopHeight[l] = h;
                surface.lesionTops[l] = v - h * radial;
            }
        }
        for (size_t p = 0; p < findings.diverticula.size(); ++p) {
            const double radius = findings.diverticula[p].diameter / 2.0;
            const double d = (v - pocketCentres[p]).norm();
            if (d < radius) {
                relief -=
                    findings.diverticula[p].diameter * (1.0 + std::cos(std::numbers::pi * d / radius)) / 2.0;
                surface.finding[4 * iu + 3] =
                    std::max(surface.finding[4 * iu + 3], static_cast<float>(1.0 - d / radius));
            }
        }
        if (relief != 0.0 && radial.allFinite()) {
            surface.rest.vertices.col(i) = v - relief * radial;
        }
    }
    return surface;
}

}  // namespace colonosim::render
