#pragma once
/// \file
/// A centreline sampled by arc length, with a rotation-minimising frame
/// (parallel transport), local lumen radius and the segment at each sample.

#include "simcore/geometry/Segment.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::geometry {

struct Centreline {
    std::vector<Eigen::Vector3d> points;    ///< m
    std::vector<double> arcLength;          ///< from the first point, m
    std::vector<Eigen::Vector3d> tangents;  ///< unit
    std::vector<Eigen::Vector3d> normals;   ///< unit, rotation-minimising, normal to the tangent
    std::vector<double> radius;             ///< distended lumen radius, m
    std::vector<Segment> segment;

    [[nodiscard]] int numPoints() const { return static_cast<int>(points.size()); }
    [[nodiscard]] double length() const { return arcLength.empty() ? 0.0 : arcLength.back(); }
};

}  // namespace colonosim::geometry
