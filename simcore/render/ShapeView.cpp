#include "simcore/render/ShapeView.h"

#include "simcore/render/Shaders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace colonosim::render {

namespace {
/// A panel: which world axes go to the image's x and y, and where it sits in NDC.
struct Panel {
    int xAxis;
    double xSign;
    double left;
    double right;
};
}  // namespace

ShapeView::ShapeView(const GlFunctions& gl) : m_gl(gl)
{
    m_program = std::make_unique<ShaderProgram>(gl, std::initializer_list<const char*>{shaders::kFlatVertex},
                                                std::initializer_list<const char*>{shaders::kFlatFragment});
    gl.GenVertexArrays(1, &m_vao);
    gl.GenBuffers(1, &m_buffer);
    gl.BindVertexArray(m_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(0);
    gl.BindVertexArray(0);
}

ShapeView::~ShapeView()
{
    m_gl.DeleteBuffers(1, &m_buffer);
    m_gl.DeleteVertexArrays(1, &m_vao);
}

void ShapeView::drawPolyline(const std::vector<Eigen::Vector2d>& points,
                             const std::vector<double>& halfWidths, const Eigen::Vector4f& colour)
{
    const auto first = static_cast<GLint>(m_vertices.size() / 2);
    const auto push = [&](const Eigen::Vector2d& p) {
        m_vertices.push_back(static_cast<float>(p.x() / m_aspect));
        m_vertices.push_back(static_cast<float>(p.y()));
    };
    constexpr int kJoinSides = 12;
    for (size_t i = 0; i < points.size(); ++i) {
        const double w = halfWidths[i];
        // A disc at every node keeps the joins round.
        for (int k = 0; k < kJoinSides; ++k) {
            const double a0 = 2.0 * std::numbers::pi * k / kJoinSides;
            const double a1 = 2.0 * std::numbers::pi * (k + 1) / kJoinSides;
            push(points[i]);
            push(points[i] + w * Eigen::Vector2d(std::cos(a0), std::sin(a0)));
            push(points[i] + w * Eigen::Vector2d(std::cos(a1), std::sin(a1)));
        }
        if (i + 1 < points.size()) {
            const Eigen::Vector2d d = points[i + 1] - points[i];
            if (d.norm() < 1e-12) {
                continue;
            }
            const Eigen::Vector2d n = Eigen::Vector2d(-d.y(), d.x()).normalized();
            const double w1 = halfWidths[i + 1];
            push(points[i] + w * n);
            push(points[i] - w * n);
            push(points[i + 1] + w1 * n);
            push(points[i] - w * n);
            push(points[i + 1] - w1 * n);
            push(points[i + 1] + w1 * n);
        }
    }
    m_batches.push_back({first, static_cast<GLsizei>(m_vertices.size() / 2) - first, colour});
}

void ShapeView::drawBatches()
{
    m_gl.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
    m_gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m_vertices.size() * sizeof(float)),
                    m_vertices.data(), GL_STREAM_DRAW);
    const GLint colourUniform = m_program->uniform("uColour");
    for (const Batch& batch : m_batches) {
        m_gl.Uniform4f(colourUniform, batch.colour[0], batch.colour[1], batch.colour[2], batch.colour[3]);
        m_gl.DrawArrays(GL_TRIANGLES, batch.first, batch.count);
    }
}

void ShapeView::render(const geometry::Centreline& colon, std::span<const Eigen::Vector3d> scope,
                       std::optional<geometry::Segment> loopSegment, double scopeDiameter, int width,
                       int height, GLuint framebuffer)
{
    const GlFunctions& gl = m_gl;
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.Viewport(0, 0, width, height);
    gl.ClearColor(0.07F, 0.08F, 0.11F, 1.0F);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.Disable(GL_DEPTH_TEST);
    m_program->use();
    gl.BindVertexArray(m_vao);
    m_vertices.clear();
    m_batches.clear();

    // Common scale for both panels: the colon's extent plus a margin.
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
    Eigen::Vector3d hi = -lo;
    for (int k = 0; k < colon.numPoints(); ++k) {
        const auto ks = static_cast<size_t>(k);
        lo = lo.cwiseMin(colon.points[ks] - Eigen::Vector3d::Constant(colon.radius[ks]));
        hi = hi.cwiseMax(colon.points[ks] + Eigen::Vector3d::Constant(colon.radius[ks]));
    }
    for (const Eigen::Vector3d& p : scope) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Eigen::Vector3d centre = (lo + hi) / 2.0;
    const Eigen::Vector3d extent = (hi - lo) * 1.1;
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    m_aspect = aspect;
    // One scale (NDC y units per metre) for both panels, each half the
    // image wide: the vertical extent fits the height, the larger of the
    // two horizontal extents (x anterior view, y lateral) the panel width.
    const double scaleY = std::min(2.0 / extent.z(), aspect / std::max(extent.x(), extent.y()));
    const double scaleX = scaleY / aspect;
    const std::array<Panel, 2> panels{{{0, 1.0, -1.0, 0.0}, {1, 1.0, 0.0, 1.0}}};

    // Which scope nodes lie in the looped segment (nearest centreline sample).
    std::vector<bool> looped(scope.size(), false);
    if (loopSegment) {
        for (size_t i = 0; i < scope.size(); ++i) {
            double best = std::numeric_limits<double>::max();
            size_t nearest = 0;
            for (size_t k = 0; k < colon.points.size(); ++k) {
                const double d = (colon.points[k] - scope[i]).squaredNorm();
                if (d < best) {
                    best = d;
                    nearest = k;
                }
            }
            looped[i] = colon.segment[nearest] == *loopSegment;
        }
    }

    for (const Panel& panel : panels) {
        const double middle = (panel.left + panel.right) / 2.0;
        const auto project = [&](const Eigen::Vector3d& p) {
            const Eigen::Vector3d q = p - centre;
            return Eigen::Vector2d((middle + panel.xSign * q[panel.xAxis] * scaleX) * aspect, q.z() * scaleY);
        };
        std::vector<Eigen::Vector2d> path;
        std::vector<double> outer;
        std::vector<double> inner;
        for (int k = 0; k < colon.numPoints(); k += 4) {
            const auto ks = static_cast<size_t>(k);
            path.push_back(project(colon.points[ks]));
            outer.push_back(colon.radius[ks] * scaleY);
            inner.push_back(std::max(0.0, colon.radius[ks] * scaleY - 3.0 * 2.0 / height));
        }
        drawPolyline(path, outer, {0.62F, 0.60F, 0.56F, 1.0F});
        drawPolyline(path, inner, {0.16F, 0.15F, 0.17F, 1.0F});

        std::vector<Eigen::Vector2d> shaft;
        std::vector<double> half;
        for (const Eigen::Vector3d& p : scope) {
            shaft.push_back(project(p));
            half.push_back(std::max(scopeDiameter / 2.0 * scaleY, 2.0 / height));
        }
        drawPolyline(shaft, half, {0.30F, 0.85F, 0.45F, 1.0F});
        // The looped part on top, in the highlight colour.
        for (size_t i = 0; i < scope.size();) {
            if (!looped[i]) {
                ++i;
                continue;
            }
            std::vector<Eigen::Vector2d> run;
            std::vector<double> runHalf;
            for (; i < scope.size() && looped[i]; ++i) {
                run.push_back(shaft[i]);
                runHalf.push_back(half[i] * 1.25);
            }
            drawPolyline(run, runHalf, {1.0F, 0.45F, 0.10F, 1.0F});
        }
    }
    // Divider between the panels.
    drawPolyline({Eigen::Vector2d(0.0, -1.0), Eigen::Vector2d(0.0, 1.0)}, {1.0 / height, 1.0 / height},
                 {0.4F, 0.4F, 0.45F, 1.0F});
    drawBatches();
    gl.BindVertexArray(0);
}

}  // namespace colonosim::render
