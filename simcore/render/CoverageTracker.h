#pragma once
/// \file
/// Mucosal coverage: which wall triangles the trainee has seen.
///
/// At each update the wall is drawn from the tip through the same fisheye
/// lens into a small square ID buffer, each fragment carrying its
/// triangle's index + 1 (gl_PrimitiveID, 24 bits in RGB) only where the
/// wall is
///   - inside the image circle (the lens),
///   - within the working distance |p - lens| <= D_w,
///   - seen at incidence angle <= alpha_max (|n . v| >= cos alpha_max),
/// with depth testing, so occluded wall is not marked. A triangle with at
/// least one such pixel becomes seen for the rest of the session.
/// Coverage = sum of rest areas of seen triangles / total area, overall and
/// per segment. A lesion is "in view" when one of its triangles has a
/// pixel in the latest update.
///
/// Updates run every coverageInterval of simulated time (10 Hz by default),
/// on the render side, never in the 1 kHz loop.

#include "simcore/geometry/Segment.h"
#include "simcore/geometry/TriangleMesh.h"
#include "simcore/render/FisheyeLens.h"
#include "simcore/render/GlFunctions.h"
#include "simcore/render/RenderParameters.h"
#include "simcore/render/ShaderProgram.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace colonosim::render {

class CoverageTracker {
public:
    /// `restMesh` gives the triangles and their rest areas, `triangleSegment`
    /// one segment per triangle. Needs a current context. Throws
    /// std::invalid_argument on a size mismatch, RenderError, ParameterError.
    CoverageTracker(const GlFunctions& gl, const geometry::TriangleMesh& restMesh,
                    std::vector<geometry::Segment> triangleSegment, const RenderParameters& parameters);
    ~CoverageTracker();
    CoverageTracker(const CoverageTracker&) = delete;
    CoverageTracker& operator=(const CoverageTracker&) = delete;

    /// The triangles of each lesion (for the "lesion in view" signal).
    void setLesionTriangles(std::vector<std::vector<int>> lesionTriangles);

    /// Updates when coverageInterval has passed since the last update at
    /// simulated time `time` (s); returns whether it did.
    bool update(double time, const Eigen::Matrix3Xd& positions, const CameraPose& pose);
    /// Updates now.
    void observe(const Eigen::Matrix3Xd& positions, const CameraPose& pose);

    /// Seen area / total area.
    [[nodiscard]] double fractionSeen() const;
    /// Seen area / total area of one segment (0 when it has no triangles).
    [[nodiscard]] double fractionSeen(geometry::Segment segment) const;
    [[nodiscard]] const std::vector<std::uint8_t>& seen() const { return m_seen; }
    /// One flag per lesion: in view at the latest update.
    [[nodiscard]] const std::vector<bool>& lesionsInView() const { return m_lesionsInView; }
    [[nodiscard]] int numUpdates() const { return m_numUpdates; }

private:
    const GlFunctions& m_gl;
    RenderParameters m_parameters;
    std::unique_ptr<ShaderProgram> m_program;
    int m_size = 0;
    GLuint m_vao = 0, m_positionBuffer = 0, m_indexBuffer = 0;
    GLuint m_framebuffer = 0, m_colour = 0, m_depth = 0;
    GLsizei m_numIndices = 0;
    std::vector<double> m_area;
    std::vector<geometry::Segment> m_segment;
    std::array<double, geometry::kNumSegments> m_segmentArea{};
    double m_totalArea = 0.0;
    std::vector<std::uint8_t> m_seen;
    std::vector<std::uint8_t> m_inView;
    std::vector<std::vector<int>> m_lesionTriangles;
    std::vector<bool> m_lesionsInView;
    std::vector<float> m_upload;
    std::vector<std::uint8_t> m_pixels;
    double m_lastUpdate = -1e300;
    int m_numUpdates = 0;
};

/// Triangles with a vertex within `radius` of `centre`.
[[nodiscard]] std::vector<int> trianglesNear(const geometry::TriangleMesh& mesh,
                                             const Eigen::Vector3d& centre, double radius);

}  // namespace colonosim::render
