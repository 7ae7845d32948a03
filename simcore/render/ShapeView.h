#pragma once
/// \file
/// The scope-shape view, as on magnetic endoscope imaging: the colon's
/// outline (the silhouette of the centreline tube, radius from the
/// centreline) and the scope shaft (its node positions), in orthographic
/// projection, anterior view (patient's left on the image's right, head up)
/// and lateral view from the patient's left (anterior on the left, head up)
/// side by side. The shaft nodes lying in the segment that holds the
/// current loop are drawn in the highlight colour; the host writes the
/// loop's name (this renderer draws no text).

#include "simcore/geometry/Centreline.h"
#include "simcore/render/GlFunctions.h"
#include "simcore/render/ShaderProgram.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace colonosim::render {

class ShapeView {
public:
    /// Needs a current context whose functions are `gl`.
    explicit ShapeView(const GlFunctions& gl);
    ~ShapeView();
    ShapeView(const ShapeView&) = delete;
    ShapeView& operator=(const ShapeView&) = delete;

    /// Draws both panels into `framebuffer` (0: default) of width x height.
    /// `loopSegment`: where the current loop is, if any. `scopeDiameter` m.
    void render(const geometry::Centreline& colon, std::span<const Eigen::Vector3d> scope,
                std::optional<geometry::Segment> loopSegment, double scopeDiameter, int width, int height,
                GLuint framebuffer = 0);

private:
    /// Adds a polyline (discs at its nodes, quads between) to the frame's
    /// vertices, drawn in `colour` after what was added before it.
    void drawPolyline(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& halfWidths,
                      const Eigen::Vector4f& colour);
    /// Uploads the frame's vertices once and draws the polylines in order
    /// (one upload a frame: re-specifying a buffer between draws made the
    /// software rasteriser wait for each draw before the next).
    void drawBatches();

    struct Batch {
        GLint first;
        GLsizei count;
        Eigen::Vector4f colour;
    };

    const GlFunctions& m_gl;
    std::unique_ptr<ShaderProgram> m_program;
    GLuint m_vao = 0;
    GLuint m_buffer = 0;
    std::vector<float> m_vertices;  ///< the frame's, x y pairs
    std::vector<Batch> m_batches;   ///< the frame's polylines, in drawing order
    double m_aspect = 1.0;          ///< of the current target: polylines are built in NDC-y units
};

}  // namespace colonosim::render
