#pragma once
/// \file
/// Places the colon centreline in the abdomen and pelvis (patient LPS, metres,
/// origin at the anal verge; x left, y posterior, z superior).
///
/// Model: seven anchors at typical adult positions (anal verge, rectosigmoid
/// junction, sigmoid-descending junction, the splenic and hepatic flexure
/// corners, the ileocecal valve, the cecal base) split the colon into six
/// spans. Each span has a few interior control points displaced from the chord
/// between its anchors by `amplitude * direction` (sacral curve of the rectum,
/// the redundant sigmoid loop rising anteriorly out of the pelvis, the
/// descending and ascending colon bulging laterally, the transverse colon a
/// wide U sagging anteriorly and caudally). The control polygon's corners are
/// rounded by circular arcs (FilletedPolyline): the curve is G1 and its
/// tightest bend is known from the polygon. Each anchor's boundary is the
/// curve point closest to it (its arc's midpoint); a flexure is the stretch of
/// its declared length centred on the bend around its corner, half of it in
/// each neighbouring span. The amplitude of each span is solved (bisection,
/// Gauss-Seidel over spans) so that its arc length equals the declared lengths
/// it holds, so every segment has its declared length; when a span is shorter
/// than its anchors' chord, the whole anchor layout is shrunk (a smaller
/// body). The longer a segment, the larger its loop: a 70 cm transverse colon
/// sags into the pelvis.
///
/// Rule: the centreline's bend radius is at least twice the lumen radius.
/// On the inner side of a bend of radius R a tube of radius r is compressed by
/// r / R: the rings of a mass-spring wall crowd there (small node masses, stiff
/// short springs, a tiny stable time step), a swept tube with R < r passes
/// through itself, and a 13 mm colonoscope cannot pass a lumen narrowed to fit
/// a kink. The layout meets the rule by construction (the polygon is coarse
/// where it turns, the fillets are as round as its edges allow) and is tested
/// for it on short, typical and redundant colons.
///
/// The radius blends between the segments' declared diameters with a smoothstep
/// over +-3 cm (at most half the shorter neighbour) around each boundary.
/// Safety net only: where the bend radius 1/kappa is still smaller than the
/// lumen radius / kMaxBendRatio, the lumen is narrowed to kMaxBendRatio / kappa
/// (eroded and averaged over +-25 mm).

#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/geometry/Centreline.h"

#include <Eigen/Core>

#include <array>

namespace colonosim::geometry {

/// Smallest centreline bend radius, in lumen radii, the layout is built for.
inline constexpr double kMinBendRadiusRatio = 2.0;

/// Largest lumen radius times centreline curvature the layout allows (safety net).
inline constexpr double kMaxBendRatio = 0.85;

struct ColonLayout {
    Centreline centreline;
    /// Arc length where segment i starts; entry kNumSegments is the total length, m.
    std::array<double, kNumSegments + 1> segmentStart{};
    /// Station positions (segment boundaries, on the curve), m.
    std::array<Eigen::Vector3d, kNumSegments + 1> stations{};
    /// Factor applied to the default station layout (1 = typical adult).
    double bodyScale = 1.0;
};

/// Lays out the centreline for `params`, sampled every `sampleSpacing` metres
/// (or finer, so that the samples are evenly spaced). Throws
/// params::ParameterError when `params` is invalid.
[[nodiscard]] ColonLayout layoutColon(const AnatomyParameters& params, double sampleSpacing = 0.001);

/// Where two parts of the distended lumen far apart along the colon pass
/// through each other: centreline samples i, j whose arc lengths differ by
/// more than 2 (r_i + r_j) (nearer samples meet in any bend; the pairing rule
/// of physics/LumenSelfContact.h) and whose centres are less than r_i + r_j
/// apart. The layout keeps each bend round (the rule above) but not the
/// colon's parts apart: a long transverse colon sagging into the pelvis can
/// run through the sigmoid's loop (11 of generated seeds 1-200; seed 7's 36 mm
/// deep). `colonosim case generate` and `case validate` name it.
struct LumenSelfOverlap {
    int pairs = 0;         ///< sample pairs that overlap
    double deepest = 0.0;  ///< largest r_i + r_j - |c_i - c_j|, m
    double arcA = 0.0;     ///< where the deepest pair lies along the colon, m (arcA < arcB)
    double arcB = 0.0;
};

[[nodiscard]] LumenSelfOverlap lumenSelfOverlap(const Centreline& centreline);

}  // namespace colonosim::geometry
