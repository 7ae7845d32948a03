#include "simcore/geometry/FilletedPolyline.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace colonosim::geometry {

namespace {

Eigen::Vector3d edgeDirection(const std::vector<Eigen::Vector3d>& p, std::size_t i)
{
    return (p[i + 1] - p[i]).normalized();
}

/// Point at angle phi in [0, theta_i] along the fillet of interior vertex i.
Eigen::Vector3d arcPoint(const FilletedPolyline& f, std::size_t i, double phi)
{
    const Eigen::Vector3d in = edgeDirection(f.points, i - 1);
    const Eigen::Vector3d out = edgeDirection(f.points, i);
    const Eigen::Vector3d inward = (out - out.dot(in) * in).normalized();
    const double r = f.bendRadius[i];
    const Eigen::Vector3d centre = f.points[i] - f.tangentLength[i] * in + r * inward;
    return centre + r * (std::sin(phi) * in - std::cos(phi) * inward);
}

}  // namespace

Eigen::Vector3d FilletedPolyline::pointAt(double s) const
{
    s = std::clamp(s, 0.0, length());
    const auto next = std::upper_bound(vertexArcLength.begin(), vertexArcLength.end(), s);
    const auto i = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        next - vertexArcLength.begin() - 1, 0, static_cast<std::ptrdiff_t>(points.size()) - 2));
    double t = s - vertexArcLength[i];
    const double halfArc = 0.5 * bendRadius[i] * turn[i];
    if (t < halfArc) {
        return arcPoint(*this, i, 0.5 * turn[i] + t / bendRadius[i]);
    }
    t -= halfArc;
    const double straight =
        std::max(0.0, (points[i + 1] - points[i]).norm() - tangentLength[i] - tangentLength[i + 1]);
    if (t <= straight || bendRadius[i + 1] <= 0.0) {
        return points[i] + (tangentLength[i] + t) * edgeDirection(points, i);
    }
    return arcPoint(*this, i + 1, std::min(turn[i + 1], (t - straight) / bendRadius[i + 1]));
}

FilletedPolyline filletPolyline(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<double>& lumenRadius)
{
    const std::size_t n = points.size();
    FilletedPolyline f;
    f.points = points;
    f.turn.assign(n, 0.0);
    f.bendRadius.assign(n, 0.0);
    f.tangentLength.assign(n, 0.0);
    f.vertexArcLength.assign(n, 0.0);
    std::vector<double> ask(n, 0.0);  // w_i = r_i tan(theta_i / 2)
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const Eigen::Vector3d in = edgeDirection(points, i - 1);
        const Eigen::Vector3d out = edgeDirection(points, i);
        f.turn[i] = std::atan2(in.cross(out).norm(), in.dot(out));
        ask[i] = f.turn[i] > 1e-9 ? lumenRadius[i] * std::tan(0.5 * f.turn[i]) : 0.0;
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (ask[i] <= 0.0) {
            continue;
        }
        const double before = (points[i] - points[i - 1]).norm() / (ask[i - 1] + ask[i]);
        const double after = (points[i + 1] - points[i]).norm() / (ask[i] + ask[i + 1]);
        const double ratio = std::min(before, after);  // R_i / r_i
        f.bendRadius[i] = ratio * lumenRadius[i];
        f.tangentLength[i] = ratio * ask[i];
    }
    for (std::size_t i = 1; i < n; ++i) {
        const double edge = (points[i] - points[i - 1]).norm();
        const double straight = std::max(0.0, edge - f.tangentLength[i - 1] - f.tangentLength[i]);
        f.vertexArcLength[i] = f.vertexArcLength[i - 1] + 0.5 * f.bendRadius[i - 1] * f.turn[i - 1] +
                               straight + 0.5 * f.bendRadius[i] * f.turn[i];
    }
    return f;
}

}  // namespace colonosim::geometry
