#pragma once
/// \file
/// Cross-sections of a tube as iso-contours of a scalar field on its surface
/// (marching triangles over the piecewise-linear field): each section's
/// length-weighted centroid, mean distance from it (radius) and length.

#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::geometry::surface {

/// One cross-section: the iso-contour of a scalar field at one level.
struct Section {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< length-weighted centroid of the contour
    double radius = 0.0;  ///< length-weighted mean distance of the contour from the centre
    double contourLength = 0.0;
};

/// Iso-contours of the piecewise-linear `field` at levels first + k step,
/// k = 0..count-1. Each triangle visits only the levels inside its value
/// range, so the cost is O(F + number of contour segments).
[[nodiscard]] std::vector<Section> levelSets(const TriangleMesh& mesh, const std::vector<double>& field,
                                             double first, double step, int count);

}  // namespace colonosim::geometry::surface
