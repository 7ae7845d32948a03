#pragma once
/// \file
/// Places the colon centreline in the abdomen and pelvis (patient LPS, metres,
/// origin at the anal verge; x left, y posterior, z superior).
///
/// Model: nine stations (anal verge, rectosigmoid junction, sigmoid-descending
/// junction, the two ends of each flexure, the ileocecal valve, the cecal base)
/// fixed at typical adult positions, and for each segment a few interior
/// control points displaced from the chord by `amplitude * direction`
/// (sacral curve of the rectum, the redundant sigmoid loop rising anteriorly
/// out of the pelvis, the transverse colon sagging anteriorly and caudally, the
/// flexures bulging cranio-laterally). A centripetal Catmull-Rom spline passes
/// through all control points (C1, no cusps; Yuksel et al. 2011). The
/// amplitude of each segment is solved (bisection, Gauss-Seidel over segments)
/// so that the arc length between its stations equals its declared length;
/// when a declared length is shorter than the station chord, the whole station
/// layout is shrunk (a smaller body). The longer a segment, the larger its
/// loop: a 70 cm transverse colon sags into the pelvis.
///
/// The radius blends between the segments' declared diameters with a smoothstep
/// over +-3 cm (at most half the shorter neighbour) around each boundary.
/// Where the bend radius 1/kappa of a flexure is smaller than the lumen radius
/// the lumen is narrowed to kMaxBendRatio / kappa (eroded and averaged over
/// +-25 mm): the wall bunches on the inner side of a sharp flexure, and a swept
/// tube wider than its bend radius would pass through itself.

#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/geometry/Centreline.h"

#include <Eigen/Core>

#include <array>

namespace colonosim::geometry {

/// Largest lumen radius times centreline curvature the layout allows.
inline constexpr double kMaxBendRatio = 0.85;

struct ColonLayout {
    Centreline centreline;
    /// Arc length where segment i starts; entry kNumSegments is the total length, m.
    std::array<double, kNumSegments + 1> segmentStart{};
    /// Station positions (segment boundaries), m.
    std::array<Eigen::Vector3d, kNumSegments + 1> stations{};
    /// Factor applied to the default station layout (1 = typical adult).
    double bodyScale = 1.0;
};

/// Lays out the centreline for `params`, sampled every `sampleSpacing` metres
/// (or finer, so that the samples are evenly spaced). Throws
/// params::ParameterError when `params` is invalid.
[[nodiscard]] ColonLayout layoutColon(const AnatomyParameters& params, double sampleSpacing = 0.001);

}  // namespace colonosim::geometry
