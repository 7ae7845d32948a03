#include "simcore/render/CentrelineChart.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace colonosim::render {

namespace {
int nearestIn(const geometry::Centreline& centreline, const Eigen::Vector3d& p, int from, int to)
{
    int best = from;
    double bestDistance = std::numeric_limits<double>::max();
    for (int k = from; k <= to; ++k) {
        const double d = (centreline.points[static_cast<size_t>(k)] - p).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}
}  // namespace

std::vector<int> nearestCentrelineSamples(const geometry::TriangleMesh& mesh,
                                          const geometry::Centreline& centreline)
{
    if (centreline.numPoints() < 2) {
        throw std::invalid_argument("centreline: needs at least two samples, has " +
                                    std::to_string(centreline.numPoints()));
    }
    // Nearest samples of consecutive vertices are close: search a window
    // around the previous one first, and the whole centreline when the
    // window's best lies on its edge.
    constexpr int kWindow = 40;
    const int last = centreline.numPoints() - 1;
    std::vector<int> samples(static_cast<size_t>(mesh.numVertices()));
    int previous = 0;
    for (int i = 0; i < mesh.numVertices(); ++i) {
        const Eigen::Vector3d v = mesh.vertices.col(i);
        const int from = std::max(0, previous - kWindow);
        const int to = std::min(last, previous + kWindow);
        int k = nearestIn(centreline, v, from, to);
        if ((k == from && from > 0) || (k == to && to < last)) {
            k = nearestIn(centreline, v, 0, last);
        }
        samples[static_cast<size_t>(i)] = k;
        previous = k;
    }
    return samples;
}

std::vector<float> centrelineChart(const geometry::TriangleMesh& mesh, const geometry::Centreline& centreline,
                                   const std::vector<int>& nearestSamples)
{
    std::vector<float> chart(static_cast<size_t>(mesh.numVertices()) * 3);
    for (int i = 0; i < mesh.numVertices(); ++i) {
        const auto iu = static_cast<size_t>(i);
        const auto k = static_cast<size_t>(nearestSamples[iu]);
        const Eigen::Vector3d offset = mesh.vertices.col(i) - centreline.points[k];
        const Eigen::Vector3d& normal = centreline.normals[k];
        const Eigen::Vector3d binormal = centreline.tangents[k].cross(normal);
        const double theta = std::atan2(offset.dot(binormal), offset.dot(normal));
        chart[3 * iu] = static_cast<float>(centreline.arcLength[k] + offset.dot(centreline.tangents[k]));
        chart[3 * iu + 1] = static_cast<float>(centreline.radius[k] * std::cos(theta));
        chart[3 * iu + 2] = static_cast<float>(centreline.radius[k] * std::sin(theta));
    }
    return chart;
}

}  // namespace colonosim::render
