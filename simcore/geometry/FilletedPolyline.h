#pragma once
/// \file
/// A control polygon whose interior corners are rounded by circular arcs
/// (fillets), the way a pipe is bent.
///
/// Model: at each interior vertex P_i the polygon turns by theta_i. The corner
/// is replaced by the circular arc of radius R_i tangent to both edges; its
/// tangent points lie d_i = R_i tan(theta_i / 2) before and after P_i, and the
/// arc's midpoint is the curve point closest to P_i. Between the arcs the curve
/// follows the edges. The curve is G1 (tangent continuous) and its curvature is
/// 0 or 1 / R_i, so its tightest bend is known exactly from the polygon.
///
/// Radii: each vertex asks for tangent length w_i = r_i tan(theta_i / 2) per
/// unit of the bend-radius ratio, r_i being its lumen radius. Each edge is
/// shared between its two end vertices in proportion to what they ask, and a
/// vertex keeps the smaller of its two shares:
///   R_i / r_i = min(|e_{i-1}| / (w_{i-1} + w_i), |e_i| / (w_i + w_{i+1})).
/// Neighbouring arcs then meet without a straight piece, and the two ends of an
/// edge bend equally tightly relative to their lumen: the polygon is rounded
/// as much as its edges allow.

#include <Eigen/Core>

#include <vector>

namespace colonosim::geometry {

struct FilletedPolyline {
    std::vector<Eigen::Vector3d> points;  ///< control polygon
    std::vector<double> turn;             ///< theta_i, rad (0 at the two ends)
    std::vector<double> bendRadius;       ///< R_i, m (0 where the polygon is straight)
    std::vector<double> tangentLength;    ///< d_i, m
    /// Arc length, from the first point, of the curve point closest to each vertex (its arc's midpoint), m.
    std::vector<double> vertexArcLength;

    /// Length of the rounded curve, m.
    [[nodiscard]] double length() const { return vertexArcLength.back(); }

    /// Point of the rounded curve at arc length s (clamped to [0, length]).
    [[nodiscard]] Eigen::Vector3d pointAt(double s) const;
};

/// Rounds the corners of `points` (at least two, no two consecutive equal, no
/// U-turn) with the radii described above; `lumenRadius[i]` is r_i.
[[nodiscard]] FilletedPolyline filletPolyline(const std::vector<Eigen::Vector3d>& points,
                                              const std::vector<double>& lumenRadius);

}  // namespace colonosim::geometry
