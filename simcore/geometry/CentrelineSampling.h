#pragma once
/// \file
/// Arc-length parametrisation of a centreline and its rotation-minimising
/// frame. Frames are propagated by parallel transport (Bishop 1975; the double
/// reflection method of Wang et al., ACM TOG 2008): each normal is reflected
/// twice so that it turns only as much as the tangent does, with no twist.

#include "simcore/geometry/Centreline.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::geometry {

/// One interpolated point of a centreline at a given arc length.
struct CentrelineSample {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
    Eigen::Vector3d binormal = Eigen::Vector3d::UnitY();  ///< tangent x normal
    double radius = 0.0;
    Segment segment = Segment::Rectum;
};

/// Resamples a polyline at `numSamples` points evenly spaced in arc length
/// (linear interpolation between the input points). Fills points and
/// arcLength only.
[[nodiscard]] std::vector<Eigen::Vector3d> resampleByArcLength(const std::vector<Eigen::Vector3d>& polyline,
                                                               int numSamples);

/// Computes arcLength, tangents (central differences) and rotation-minimising
/// normals from `points`. The first normal is `firstNormalHint` made
/// orthogonal to the first tangent (any perpendicular if they are parallel).
void computeArcLengthAndFrames(Centreline& centreline, const Eigen::Vector3d& firstNormalHint);

/// Interpolates the centreline at arc length `s` (clamped to [0, length]).
[[nodiscard]] CentrelineSample sampleCentreline(const Centreline& centreline, double s);

}  // namespace colonosim::geometry
