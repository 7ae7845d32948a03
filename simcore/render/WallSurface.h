#pragma once
/// \file
/// What the renderer knows of the wall besides its shape: texture chart,
/// findings and preparation, per visual vertex, fixed at load time.
///
/// Chart: a centreline parameterisation. Each rest vertex v takes the arc
/// length s = s_k + (v - c_k).t_k from its nearest centreline sample k and
/// the clock angle theta = atan2((v - c_k).b, (v - c_k).n) in that sample's
/// rotation-minimising frame (n, b = t x n), the frame ProceduralColon
/// builds its rings in. The chart is stored as the point of the straightened
/// (unrolled-free) cylinder (s, r cos theta, r sin theta), r the centreline
/// radius, and the procedural textures are 3D noise of it: no seam at
/// theta = +-pi and no stretching around the circumference. Because the
/// chart is fixed at rest, textures move with the tissue when it deforms.
///
/// Findings are relief on the rest mesh, moved along the inward radial
/// direction (towards the centreline) by a height profile h(d) of the
/// distance d from the finding's centre on the wall, within its radius R:
///   pedunculated: H = 1.2 D, h = H (1 - (d/R)^2)^0.35 (steep stalk, round head)
///   sessile:      H = 0.5 D, h = H sqrt(1 - (d/R)^2)  (dome)
///   flat (0-IIa): H = 1.5 mm, h = H (1 - (d/R)^2)
///   depressed:    H = -1 mm
///   diverticulum: a pocket outwards, depth D, h = -D (1 + cos(pi d / R)) / 2,
/// and a colour weight fading over the outer fifth of R. Each vertex within
/// 2 R of a lesion carries the tissue code of the nearest one (by d / R), so
/// the code does not blend with another's across a lesion's rim.
/// Tissue: adenoma (reddish, pit pattern), serrated (pale, mucus cap), cancer
/// (dark red, irregular), lipoma (a submucosal fat mound under intact mucosa:
/// yellow through the normal mucosa and its vessels, smooth, no pit pattern).
/// Diverticulum: the shader darkens its mouth to a black opening (the light
/// guides beside the lens do not reach into the sac behind the neck).
/// Residual fluid: pools at their level (ResidualFluid.h); each vertex
/// carries its depth below the surface for the shader.

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/Segment.h"
#include "simcore/geometry/TriangleMesh.h"
#include "simcore/render/ResidualFluid.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace colonosim::render {

enum class LesionShape : std::uint8_t { Pedunculated, Sessile, Flat, Depressed };
/// The numeric values are the shader's tissue codes (Shaders.h, kWallFragment).
enum class LesionTissue : std::uint8_t { Adenoma = 0, Serrated = 1, Cancer = 2, Lipoma = 3 };

/// A place on the wall: arc length along the centreline (m), clock angle (rad).
struct WallPlace {
    double arcLength = 0.0;
    double angle = 0.0;

    bool operator==(const WallPlace&) const = default;
};

struct Lesion {
    WallPlace place;
    double diameter = 0.01;  ///< m
    LesionShape shape = LesionShape::Sessile;
    LesionTissue tissue = LesionTissue::Adenoma;
};

struct Diverticulum {
    WallPlace place;
    double diameter = 0.006;  ///< m
};

/// A contact bleeding mark (a submucosal haemorrhage from the scope's
/// pressure): a dark-red spot of `radius` around the chart place of
/// `restPoint` (chartPlaceAt), drawn over the mucosa with `opacity`, with a
/// noise-edged rim from the chart's relief.
struct BleedingMark {
    Eigen::Vector3d restPoint = Eigen::Vector3d::Zero();  ///< m, the marked wall point at rest
    double radius = 0.002;                                ///< m, on the wall
    double opacity = 0.6;                                 ///< 0..1

    bool operator==(const BleedingMark&) const = default;
};

/// The most bleeding marks a view draws (the rest are ignored).
inline constexpr int kMaxBleedingMarks = 64;

struct WallFindings {
    std::vector<Lesion> lesions;
    std::vector<Diverticulum> diverticula;
    std::array<double, geometry::kNumSegments> stoolFraction{};  ///< fraction of mucosa covered, by Segment
    std::vector<FluidPool> fluid;                                ///< residual fluid (ResidualFluid.h)
    /// Gravity's direction in the mesh's frame (unit): patient LPS, +x in
    /// left lateral decubitus (physics::downDirection).
    Eigen::Vector3d down = Eigen::Vector3d::UnitX();
};

struct WallSurface {
    geometry::TriangleMesh rest;  ///< visual mesh at rest with the findings' relief
    std::vector<float> chart;     ///< 3 per vertex: s, r cos(theta), r sin(theta) (m)
    std::vector<float> finding;   ///< 4 per vertex: lesion weight, tissue code, stool fraction, diverticulum
    std::vector<float> fluidDepth;  ///< 1 per vertex: m below its pool's surface (ResidualFluid.h)
    Eigen::Vector3d up = -Eigen::Vector3d::UnitX();  ///< against gravity (unit), the pools' surface normal
    std::vector<geometry::Segment> vertexSegment;
    std::vector<Eigen::Vector3d> lesionTops;  ///< rest position of each lesion's highest point
};

/// The point of the distended wall (centreline radius) at a place, m.
[[nodiscard]] Eigen::Vector3d wallPoint(const geometry::Centreline& centreline, const WallPlace& place);

/// The place of the rest point `p` on `surface`'s chart: the chart of the
/// rest vertex nearest `p` (arc length, and the clock angle of its chart
/// point), so that a mark drawn at it lies where the texture puts that point.
[[nodiscard]] WallPlace chartPlaceAt(const WallSurface& surface, const Eigen::Vector3d& p);
/// The same on a rest mesh's vertices and its chart (3 floats per vertex);
/// throws std::invalid_argument when their sizes disagree.
[[nodiscard]] WallPlace chartPlaceAt(const Eigen::Matrix3Xd& restVertices, const std::vector<float>& chart,
                                     const Eigen::Vector3d& p);

/// Builds the chart, findings, relief and fluid depths for `visualRest`.
/// Throws std::invalid_argument when the centreline has fewer than two
/// samples, `findings.down` is zero or not finite or a pool's volume is
/// negative or not finite.
[[nodiscard]] WallSurface buildWallSurface(const geometry::TriangleMesh& visualRest,
                                           const geometry::Centreline& centreline,
                                           const WallFindings& findings);

}  // namespace colonosim::render
