#include "simcore/render/WallSurface.h"

#include "simcore/render/CentrelineChart.h"
#include "simcore/render/LaplaceChart.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace colonosim::render {

namespace {
/// Reach of a lesion's tissue code, in lesion radii (WallSurface.h).
constexpr double kTissueReach = 2.0;

int sampleAt(const geometry::Centreline& centreline, double arcLength)
{
    const auto it = std::lower_bound(centreline.arcLength.begin(), centreline.arcLength.end(), arcLength);
    const int k = static_cast<int>(it - centreline.arcLength.begin());
    return std::clamp(k, 0, centreline.numPoints() - 1);
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

WallPlace chartPlaceAt(const Eigen::Matrix3Xd& restVertices, const std::vector<float>& chart,
                       const Eigen::Vector3d& p)
{
    if (restVertices.cols() == 0 || chart.size() != 3 * static_cast<size_t>(restVertices.cols())) {
        throw std::invalid_argument("chartPlaceAt: " + std::to_string(chart.size()) + " chart values for " +
                                    std::to_string(restVertices.cols()) + " vertices; 3 per vertex required");
    }
    Eigen::Index nearest = 0;
    (restVertices.colwise() - p).colwise().squaredNorm().minCoeff(&nearest);
    const auto k = static_cast<size_t>(nearest);
    return {chart[3 * k], std::atan2(chart[3 * k + 2], chart[3 * k + 1])};
}

WallPlace chartPlaceAt(const WallSurface& surface, const Eigen::Vector3d& p)
{
    return chartPlaceAt(surface.rest.vertices, surface.chart, p);
}

WallSurface buildWallSurface(const geometry::TriangleMesh& visualRest, const geometry::Centreline& centreline,
                             const WallFindings& findings)
{
    if (centreline.numPoints() < 2) {
        throw std::invalid_argument("buildWallSurface: the centreline needs at least two samples");
    }
    if (!findings.down.allFinite() || findings.down.norm() < 1e-9) {
        throw std::invalid_argument("buildWallSurface: the down direction must be a finite, non-zero vector");
    }
    for (const FluidPool& pool : findings.fluid) {
        if (!(pool.volume >= 0.0) || !std::isfinite(pool.volume)) {
            throw std::invalid_argument(
                "buildWallSurface: residual fluid volume = " + std::to_string(pool.volume) +
                " m^3; a finite volume of at least 0 is required");
        }
    }
    WallSurface surface;
    surface.rest = visualRest;
    const int n = visualRest.numVertices();
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

    const std::vector<int> nearest = nearestCentrelineSamples(visualRest, centreline);
    surface.chart = laplaceChart(visualRest, centreline);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d v = visualRest.vertices.col(i);
        const auto iu = static_cast<size_t>(i);
        const auto ks = static_cast<size_t>(nearest[iu]);
        const Eigen::Vector3d offset = v - centreline.points[ks];
        surface.vertexSegment[iu] = centreline.segment[ks];
        surface.finding[4 * iu + 2] =
            static_cast<float>(findings.stoolFraction[static_cast<size_t>(centreline.segment[ks])]);

        // Radial direction, outwards; relief moves the vertex against it.
        const Eigen::Vector3d radial =
            (offset - offset.dot(centreline.tangents[ks]) * centreline.tangents[ks]).normalized();
        double relief = 0.0;
        double nearestLesion = kTissueReach;  // d / R of the nearest lesion
        for (size_t l = 0; l < findings.lesions.size(); ++l) {
            const double d = (v - lesionCentres[l]).norm();
            const auto [h, weight] = lesionRelief(findings.lesions[l], d);
            surface.finding[4 * iu] = std::max(surface.finding[4 * iu], static_cast<float>(weight));
            if (d / (findings.lesions[l].diameter / 2.0) < nearestLesion) {
                nearestLesion = d / (findings.lesions[l].diameter / 2.0);
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
    surface.up = -findings.down.normalized();
    surface.fluidDepth =
        fluidDepths(surface.rest.vertices, nearest, centreline, findings.fluid, findings.down);
    return surface;
}

}  // namespace colonosim::render
