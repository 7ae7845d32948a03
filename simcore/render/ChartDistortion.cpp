#include "simcore/render/ChartDistortion.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace colonosim::render {

namespace {

struct Weighted {
    double value = 0.0;
    double weight = 0.0;
};

DistortionStatistic statistic(std::vector<Weighted> samples)
{
    DistortionStatistic out;
    std::sort(samples.begin(), samples.end(),
              [](const Weighted& a, const Weighted& b) { return a.value < b.value; });
    double total = 0.0;
    for (const Weighted& w : samples) {
        total += w.weight;
        out.mean += w.weight * w.value;
    }
    out.mean /= total;
    out.max = samples.back().value;
    double cumulative = 0.0;
    bool have95 = false;
    bool have99 = false;
    for (const Weighted& w : samples) {
        cumulative += w.weight;
        if (!have95 && cumulative >= 0.95 * total) {
            out.p95 = w.value;
            have95 = true;
        }
        if (!have99 && cumulative >= 0.99 * total) {
            out.p99 = w.value;
            have99 = true;
        }
    }
    if (!have99) {
        out.p99 = out.max;
        out.p95 = have95 ? out.p95 : out.max;
    }
    return out;
}

}  // namespace

TriangleStretch triangleStretch(const std::array<Eigen::Vector3d, 3>& surface,
                                const std::array<Eigen::Vector2d, 3>& chart)
{
    const Eigen::Vector3d e1 = surface[1] - surface[0];
    const Eigen::Vector3d e2 = surface[2] - surface[0];
    const Eigen::Vector3d normal = e1.cross(e2);
    if (e1.norm() == 0.0 || normal.norm() == 0.0) {
        return {0.0, 0.0, 0.0};
    }
    // The triangle in its own plane: x along e1, y in the plane, x cross y = normal.
    const Eigen::Vector3d x = e1.normalized();
    const Eigen::Vector3d y = normal.normalized().cross(x);
    Eigen::Matrix2d planar;
    planar << e1.dot(x), e2.dot(x), e1.dot(y), e2.dot(y);
    Eigen::Matrix2d image;
    image.col(0) = chart[1] - chart[0];
    image.col(1) = chart[2] - chart[0];
    const Eigen::Matrix2d jacobian = image * planar.inverse();
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(jacobian);
    return {svd.singularValues()(0), svd.singularValues()(1), jacobian.determinant()};
}

ChartDistortion measureChartDistortion(const geometry::TriangleMesh& mesh, const std::vector<float>& chart)
{
    if (chart.size() != static_cast<size_t>(mesh.numVertices()) * 3) {
        throw std::invalid_argument("chart: has " + std::to_string(chart.size()) +
                                    " floats, needs 3 per vertex (" + std::to_string(3 * mesh.numVertices()) +
                                    ")");
    }
    if (mesh.numTriangles() == 0) {
        throw std::invalid_argument("mesh: has no triangles");
    }
    std::vector<TriangleStretch> stretches;
    std::vector<double> areas;
    double signedArea = 0.0;
    for (const auto& t : mesh.triangles) {
        std::array<Eigen::Vector3d, 3> surface;
        std::array<double, 3> s{};
        std::array<double, 3> theta{};
        double radius = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            const auto v = static_cast<size_t>(t[c]);
            surface[c] = mesh.vertices.col(t[c]);
            s[c] = chart[3 * v];
            theta[c] = std::atan2(chart[3 * v + 2], chart[3 * v + 1]);
            radius += std::hypot(chart[3 * v + 1], chart[3 * v + 2]) / 3.0;
        }
        std::array<Eigen::Vector2d, 3> image;
        for (size_t c = 0; c < 3; ++c) {
            const double unwrapped = theta[0] + std::remainder(theta[c] - theta[0], 2.0 * std::numbers::pi);
            image[c] = Eigen::Vector2d(s[c], radius * unwrapped);
        }
        stretches.push_back(triangleStretch(surface, image));
        areas.push_back(0.5 * (surface[1] - surface[0]).cross(surface[2] - surface[0]).norm());
        signedArea += areas.back() * stretches.back().determinant;
    }
    const double orientation = signedArea < 0.0 ? -1.0 : 1.0;

    std::vector<double> areaRatios;
    for (const TriangleStretch& t : stretches) {
        areaRatios.push_back(t.sigma1 * t.sigma2);
    }
    std::vector<double> sorted = areaRatios;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
    const double median = sorted[sorted.size() / 2];

    ChartDistortion out;
    out.numTriangles = mesh.numTriangles();
    std::vector<Weighted> stretch;
    std::vector<Weighted> area;
    for (size_t i = 0; i < stretches.size(); ++i) {
        const TriangleStretch& t = stretches[i];
        const double ratio = median > 0.0 ? areaRatios[i] / median : 0.0;
        if (t.determinant * orientation <= 0.0 || ratio < 1e-3) {
            ++out.numTears;
        }
        const double conformal =
            t.sigma2 > 0.0 ? t.sigma1 / t.sigma2 : std::numeric_limits<double>::infinity();
        stretch.push_back({conformal, areas[i]});
        area.push_back({ratio, areas[i]});
    }
    out.stretch = statistic(std::move(stretch));
    out.areaRatio = statistic(std::move(area));
    return out;
}

}  // namespace colonosim::render
