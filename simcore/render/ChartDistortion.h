#pragma once
/// \file
/// How much a texture chart distorts the wall. Each triangle, in its own
/// plane, is mapped affinely onto its image in the chart plane (s, r theta),
/// theta unwrapped across the +-pi seam to within pi of the first corner's,
/// r the mean chart radius of its corners. The map's Jacobian J (2 x 2) has
/// singular values sigma1 >= sigma2:
///   stretch    sigma1 / sigma2   (conformal distortion, 1 for a similarity),
///   area ratio sigma1 sigma2 / median over triangles (1 where areas keep
///              their proportion).
/// Statistics are weighted by the triangle's surface area. A tear is a
/// triangle whose image is flipped (det J of the other sign than the
/// area-weighted majority) or degenerate (area ratio below 1e-3).

#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace colonosim::render {

/// Singular values of the affine map of one triangle onto its chart image.
struct TriangleStretch {
    double sigma1 = 1.0;     ///< larger singular value
    double sigma2 = 1.0;     ///< smaller singular value
    double determinant = 1;  ///< det J, negative when the image is flipped
};

/// Area-weighted statistics of one quantity over the triangles.
struct DistortionStatistic {
    double mean = 0.0;
    double p95 = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};

struct ChartDistortion {
    DistortionStatistic stretch;    ///< sigma1 / sigma2
    DistortionStatistic areaRatio;  ///< sigma1 sigma2 / its median
    int numTears = 0;               ///< flipped or degenerate images
    int numTriangles = 0;
};

/// The map from `surface` (3D, its own plane; m) onto `chart` (2D). A
/// degenerate surface triangle gives sigma1 = sigma2 = determinant = 0.
[[nodiscard]] TriangleStretch triangleStretch(const std::array<Eigen::Vector3d, 3>& surface,
                                              const std::array<Eigen::Vector2d, 3>& chart);

/// Measures `chart` (3 per vertex: s, r cos theta, r sin theta) on `mesh`.
/// Throws std::invalid_argument when the chart's size is not 3 per vertex or
/// the mesh has no triangles.
[[nodiscard]] ChartDistortion measureChartDistortion(const geometry::TriangleMesh& mesh,
                                                     const std::vector<float>& chart);

}  // namespace colonosim::render
