#include "simcore/render/EndoscopeView.h"

#include "simcore/geometry/MeshMapping.h"
#include "simcore/render/Shaders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace colonosim::render {

namespace {
void setCamera(const GlFunctions& gl, const ShaderProgram& program, const CameraPose& pose,
               double fieldOfView, double aspect, double nearDistance, double farDistance)
{
    const Eigen::Matrix3f w = worldToCamera(pose).cast<float>();
    gl.UniformMatrix3fv(program.uniform("uWorldToCamera"), 1, GL_FALSE, w.data());  // column-major
    const Eigen::Vector3f p = pose.position.cast<float>();
    gl.Uniform3f(program.uniform("uCameraPosition"), p.x(), p.y(), p.z());
    gl.Uniform1f(program.uniform("uHalfFieldOfView"), static_cast<float>(fieldOfView / 2.0));
    gl.Uniform1f(program.uniform("uAspect"), static_cast<float>(aspect));
    gl.Uniform2f(program.uniform("uDepthRange"), static_cast<float>(nearDistance),
                 static_cast<float>(farDistance));
}
}  // namespace

EndoscopeView::EndoscopeView(const GlFunctions& gl, const WallSurface& surface,
                             const RenderParameters& parameters)
    : m_gl(gl), m_parameters(parameters), m_levels(surface.rest.triangles, surface.rest.vertices),
      m_triangles(surface.rest.triangles), m_chart(surface.chart), m_restVertices(surface.rest.vertices),
      m_up(surface.up.normalized())
{
    m_parameters.validate();
    // The residual fluid's shading is compiled in only where the wall has fluid (Shaders.h).
    const bool fluid = std::any_of(surface.fluidDepth.begin(), surface.fluidDepth.end(),
                                   [](float depth) { return depth > 0.0F; });
    m_wall = std::make_unique<ShaderProgram>(
        gl, std::initializer_list<const char*>{shaders::kFisheye, shaders::kWallVertex},
        std::initializer_list<const char*>{fluid ? "#define RESIDUAL_FLUID\n" : "", shaders::kWallFragment});
    m_lens = std::make_unique<ShaderProgram>(
        gl, std::initializer_list<const char*>{shaders::kScreenVertex},
        std::initializer_list<const char*>{shaders::kNoise, shaders::kLensFragment});
    m_lensMask = std::make_unique<ShaderProgram>(
        gl, std::initializer_list<const char*>{shaders::kScreenVertex},
        std::initializer_list<const char*>{shaders::kNoise, shaders::kLensMaskFragment});
    m_lensReduce =
        std::make_unique<ShaderProgram>(gl, std::initializer_list<const char*>{shaders::kScreenVertex},
                                        std::initializer_list<const char*>{shaders::kLensReduceFragment});
    m_cleanLens = std::make_unique<ShaderProgram>(
        gl, std::initializer_list<const char*>{shaders::kScreenVertex},
        std::initializer_list<const char*>{"#define LENS_CLEAN\n", shaders::kNoise, shaders::kLensFragment});
    const auto numVertices = static_cast<size_t>(surface.rest.numVertices());
    gl.GenVertexArrays(1, &m_vao);
    gl.GenVertexArrays(1, &m_screenVao);
    gl.BindVertexArray(m_vao);

    gl.GenBuffers(1, &m_dynamicBuffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, m_dynamicBuffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(numVertices * 6 * sizeof(float)), nullptr,
                  GL_STREAM_DRAW);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                           reinterpret_cast<void*>(3 * sizeof(float)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);

    constexpr size_t kFixed = 8;  // chart (3), finding (4), fluid depth (1)
    std::vector<float> fixed(numVertices * kFixed);
    for (size_t i = 0; i < numVertices; ++i) {
        std::copy_n(surface.chart.begin() + static_cast<long>(3 * i), 3,
                    fixed.begin() + static_cast<long>(kFixed * i));
        std::copy_n(surface.finding.begin() + static_cast<long>(4 * i), 4,
                    fixed.begin() + static_cast<long>(kFixed * i + 3));
        fixed[kFixed * i + 7] = i < surface.fluidDepth.size() ? surface.fluidDepth[i] : kDryDepth;
    }
    gl.GenBuffers(1, &m_staticBuffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, m_staticBuffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(fixed.size() * sizeof(float)), fixed.data(),
                  GL_STATIC_DRAW);
    constexpr auto kStride = static_cast<GLsizei>(kFixed * sizeof(float));
    gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    gl.VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<void*>(3 * sizeof(float)));
    gl.VertexAttribPointer(5, 1, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<void*>(7 * sizeof(float)));
    gl.EnableVertexAttribArray(2);
    gl.EnableVertexAttribArray(3);
    gl.EnableVertexAttribArray(5);

    m_bleedingNear.assign(numVertices, 0.0F);
    m_chartRadius.resize(numVertices);
    m_chartAngle.resize(numVertices);
    for (size_t v = 0; v < numVertices; ++v) {
        const double y = m_chart[3 * v + 1];
        const double z = m_chart[3 * v + 2];
        m_chartRadius[v] = std::hypot(y, z);
        m_chartAngle[v] = std::atan2(z, y);
    }
    m_byArc.resize(numVertices);
    std::iota(m_byArc.begin(), m_byArc.end(), 0);
    std::stable_sort(m_byArc.begin(), m_byArc.end(), [this](int a, int b) {
        return m_chart[3 * static_cast<size_t>(a)] < m_chart[3 * static_cast<size_t>(b)];
    });
    m_arcSorted.resize(numVertices);
    for (size_t i = 0; i < numVertices; ++i) {
        m_arcSorted[i] = m_chart[3 * static_cast<size_t>(m_byArc[i])];
    }
    gl.GenBuffers(1, &m_bleedingBuffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, m_bleedingBuffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(numVertices * sizeof(float)),
                  m_bleedingNear.data(), GL_DYNAMIC_DRAW);
    gl.VertexAttribPointer(4, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
    gl.EnableVertexAttribArray(4);

    gl.GenBuffers(1, &m_indexBuffer);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    const std::vector<std::uint32_t>& indices = m_levels.indices();
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
                  indices.data(), GL_STATIC_DRAW);
    gl.BindVertexArray(0);
    setWallPositions(surface.rest.vertices);
    bakeMucosa();
}

void EndoscopeView::bakeMucosa()
{
    constexpr int kSize = 1024;  // texels per 160 mm tile: 0.16 mm each
    const GlFunctions& gl = m_gl;
    const ShaderProgram bake(gl, {shaders::kScreenVertex}, {shaders::kPeriodicNoise, shaders::kMucosaBake});
    gl.GenTextures(1, &m_mucosa);
    gl.BindTexture(GL_TEXTURE_2D, m_mucosa);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    GLuint framebuffer = 0;
    gl.GenFramebuffers(1, &framebuffer);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_mucosa, 0);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        gl.DeleteFramebuffers(1, &framebuffer);
        throw RenderError("the mucosa texture cannot be rendered to");
    }
    gl.Viewport(0, 0, kSize, kSize);
    gl.Disable(GL_DEPTH_TEST);
    bake.use();
    drawScreenTriangle();
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &framebuffer);
    gl.GenerateMipmap(GL_TEXTURE_2D);
}

EndoscopeView::~EndoscopeView()
{
    m_gl.DeleteBuffers(1, &m_dynamicBuffer);
    m_gl.DeleteBuffers(1, &m_staticBuffer);
    m_gl.DeleteBuffers(1, &m_indexBuffer);
    m_gl.DeleteBuffers(1, &m_bleedingBuffer);
    m_gl.DeleteVertexArrays(1, &m_vao);
    m_gl.DeleteVertexArrays(1, &m_screenVao);
    m_gl.DeleteTextures(1, &m_mucosa);
    m_mask.release(m_gl);
    m_blur.release(m_gl);
    m_gl.DeleteFramebuffers(1, &m_targetFramebuffer);
    m_gl.DeleteTextures(1, &m_targetColour);
    m_gl.DeleteRenderbuffers(1, &m_targetDepth);
}

void EndoscopeView::setWallPositions(const Eigen::Matrix3Xd& positions)
{
    m_positions = positions;
    geometry::MeshMapping::computeVertexNormals(positions, m_triangles, m_normals);
    const auto n = static_cast<size_t>(positions.cols());
    m_upload.resize(n * 6);
    for (size_t i = 0; i < n; ++i) {
        const auto col = static_cast<Eigen::Index>(i);
        for (int k = 0; k < 3; ++k) {
            m_upload[6 * i + static_cast<size_t>(k)] = static_cast<float>(positions(k, col));
            m_upload[6 * i + 3 + static_cast<size_t>(k)] = static_cast<float>(m_normals(k, col));
        }
    }
    m_gl.BindBuffer(GL_ARRAY_BUFFER, m_dynamicBuffer);
    m_gl.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(m_upload.size() * sizeof(float)),
                       m_upload.data());
}

void EndoscopeView::setBleedingMarks(const std::vector<BleedingMark>& marks)
{
    const size_t count = std::min(marks.size(), static_cast<size_t>(kMaxBleedingMarks));
    if (std::equal(marks.begin(), marks.begin() + static_cast<long>(count), m_marks.begin(), m_marks.end())) {
        return;
    }
    const std::vector<BleedingMark> previous = std::move(m_marks);
    m_marks.assign(marks.begin(), marks.begin() + static_cast<long>(count));
    m_markPlaces.resize(count);
    m_markUniforms.resize(4 * count);
    // A mark darkens as it is hit again (its opacity, a uniform): the
    // vertices near the marks change only with a new mark or a wider one.
    bool sameReach = previous.size() == count;
    for (size_t k = 0; k < count; ++k) {
        const BleedingMark& mark = m_marks[k];
        // A mark keeps its rest point; only a new one is looked up on the chart.
        if (k >= previous.size() || previous[k].restPoint != mark.restPoint) {
            m_markPlaces[k] = chartPlaceAt(m_restVertices, m_chart, mark.restPoint);
        }
        const WallPlace& place = m_markPlaces[k];
        m_markUniforms[4 * k] = static_cast<float>(place.arcLength * 1000.0);
        m_markUniforms[4 * k + 1] = static_cast<float>(std::remainder(place.angle, 2.0 * std::numbers::pi));
        m_markUniforms[4 * k + 2] = static_cast<float>(mark.radius * 1000.0);
        m_markUniforms[4 * k + 3] = static_cast<float>(std::clamp(mark.opacity, 0.0, 1.0));
        sameReach = sameReach && previous[k].restPoint == mark.restPoint && previous[k].radius == mark.radius;
    }
    if (sameReach) {
        return;
    }
    // A fragment within a mark's radius lies in a triangle with a vertex
    // within the radius plus one edge (the visual mesh's edges are 2-3 mm).
    constexpr double kReach = 4e-3;  // m beyond the radius
    // Only the vertices within a mark's reach along the chart are looked at
    // (m_byArc); the window is widened by a nanometre so that rounding at its
    // ends drops none, and the test itself is the exact one.
    constexpr double kWiden = 1e-9;  // m
    std::fill(m_bleedingNear.begin(), m_bleedingNear.end(), 0.0F);
    for (size_t k = 0; k < m_marks.size(); ++k) {
        const double at = m_markPlaces[k].arcLength;
        const double reach = m_marks[k].radius + kReach;
        const auto from = std::lower_bound(m_arcSorted.begin(), m_arcSorted.end(), at - reach - kWiden);
        const auto to = std::upper_bound(from, m_arcSorted.end(), at + reach + kWiden);
        for (auto it = from; it != to; ++it) {
            const auto v = static_cast<size_t>(m_byArc[static_cast<size_t>(it - m_arcSorted.begin())]);
            const double ds = static_cast<double>(m_chart[3 * v]) - at;
            if (m_bleedingNear[v] != 0.0F || std::abs(ds) > reach) {
                continue;
            }
            const double arc = m_chartRadius[v] * std::remainder(m_chartAngle[v] - m_markPlaces[k].angle,
                                                                 2.0 * std::numbers::pi);
            if (ds * ds + arc * arc <= reach * reach) {
                m_bleedingNear[v] = 1.0F;
            }
        }
    }
    m_gl.BindBuffer(GL_ARRAY_BUFFER, m_bleedingBuffer);
    m_gl.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(m_bleedingNear.size() * sizeof(float)),
                       m_bleedingNear.data());
}

double EndoscopeView::wallDistanceAhead(const Eigen::Vector3d& point, const Eigen::Vector3d& forward,
                                        double coneAngle) const
{
    return wallDistancesAhead(point, forward, {coneAngle, coneAngle})[0];
}

std::array<double, 2> EndoscopeView::wallDistancesAhead(const Eigen::Vector3d& point,
                                                        const Eigen::Vector3d& forward,
                                                        const std::array<double, 2>& coneAngles) const
{
    const std::array<double, 2> cosCone{std::cos(coneAngles[0]), std::cos(coneAngles[1])};
    std::array<double, 2> best{std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity()};
    for (Eigen::Index i = 0; i < m_positions.cols(); ++i) {
        const Eigen::Vector3d d = m_positions.col(i) - point;
        const double along = d.dot(forward);
        if (along > 0.0) {
            const double norm = d.norm();
            for (size_t k = 0; k < 2; ++k) {
                if (along >= cosCone[k] * norm) {
                    best[k] = std::min(best[k], d.squaredNorm());
                }
            }
        }
    }
    return {std::sqrt(best[0]), std::sqrt(best[1])};
}

void EndoscopeView::resizeTarget(int width, int height)
{
    if (width == m_targetWidth && height == m_targetHeight) {
        return;
    }
    const GlFunctions& gl = m_gl;
    allocateColourDepthTarget(gl, m_targetFramebuffer, m_targetColour, m_targetDepth, width, height,
                              GL_LINEAR, "the endoscope view's offscreen target is incomplete");
    m_targetWidth = width;
    m_targetHeight = height;
}

void EndoscopeView::drawScreenTriangle() const
{
    m_gl.BindVertexArray(m_screenVao);
    m_gl.DrawArrays(GL_TRIANGLES, 0, 3);
    m_gl.BindVertexArray(0);
}

void EndoscopeView::updateLensMask(const LensState& lens, int width, int height)
{
    // The mask follows the soiling in steps of 1/64 (a drop's radius moves
    // by about 1% a step): it is drawn again only when one is crossed.
    const double amount = std::max(std::round(std::clamp(lens.soiling, 0.0, 1.0) * 64.0), 1.0) / 64.0;
    if (width == m_mask.width && height == m_mask.height && amount == m_maskSoiling &&
        lens.soilingSeed == m_maskSeed) {
        return;
    }
    const GlFunctions& gl = m_gl;
    m_mask.bind(gl, width, height, GL_R8, GL_NEAREST, "the lens soiling's mask cannot be rendered to");
    m_lensMask->use();
    gl.Uniform1f(m_lensMask->uniform("uAspect"), static_cast<float>(width) / static_cast<float>(height));
    gl.Uniform1f(m_lensMask->uniform("uSoiling"), static_cast<float>(amount));
    gl.Uniform1f(m_lensMask->uniform("uSeed"), static_cast<float>(lens.soilingSeed));
    drawScreenTriangle();
    m_maskSoiling = amount;
    m_maskSeed = lens.soilingSeed;
}

void EndoscopeView::reduceForBlur(double blurRadius, int width, int height)
{
    // A texel of about 0.45 of the blur radius, a power of two pixels
    // (mipmaps would do, but llvmpipe builds them slowly: about 10 ms at
    // 640x480, against a fraction of one for this pass).
    const int factor =
        1 << std::clamp(static_cast<int>(std::lround(std::log2(std::max(0.45 * blurRadius, 1.0)))), 0, 4);
    const int w = std::max(width / factor, 1);
    const int h = std::max(height / factor, 1);
    const GlFunctions& gl = m_gl;
    m_blur.bind(gl, w, h, GL_RGBA8, GL_LINEAR, "the lens soiling's blur cannot be rendered to");
    m_lensReduce->use();
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, m_targetColour);
    gl.Uniform1i(m_lensReduce->uniform("uScene"), 0);
    gl.Uniform2f(m_lensReduce->uniform("uOffset"),
                 static_cast<float>(factor) / 4.0F / static_cast<float>(width),
                 static_cast<float>(factor) / 4.0F / static_cast<float>(height));
    drawScreenTriangle();
}

void EndoscopeView::render(const CameraPose& pose, const LensState& lens, int width, int height,
                           GLuint framebuffer)
{
    const GlFunctions& gl = m_gl;
    resizeTarget(width, height);
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const Eigen::Vector3d forward = pose.rotation.col(2);
    // The nearest wall ahead (red-out) and within the light meter's cone.
    const std::array<double, 2> distances =
        wallDistancesAhead(pose.position, forward, {std::numbers::pi / 2.0, m_parameters.autoLightCone});
    const double ahead = std::min(distances[0], lens.wallDistance);
    m_redOut = std::clamp((m_parameters.redOutDistance - ahead) /
                              (m_parameters.redOutDistance - m_parameters.contactDistance),
                          0.0, 1.0);

    gl.BindFramebuffer(GL_FRAMEBUFFER, m_targetFramebuffer);
    gl.Viewport(0, 0, width, height);
    gl.ClearColor(0.0F, 0.0F, 0.0F, 1.0F);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_CLIP_DISTANCE0);
    m_wall->use();
    setCamera(gl, *m_wall, pose, m_parameters.fieldOfView, aspect, m_parameters.nearDistance,
              m_parameters.farDistance);
    const Eigen::Vector3f light = pose.position.cast<float>();
    const Eigen::Vector3f axis = forward.cast<float>();
    gl.Uniform3f(m_wall->uniform("uLightPosition"), light.x(), light.y(), light.z());
    gl.Uniform3f(m_wall->uniform("uViewAxis"), axis.x(), axis.y(), axis.z());
    // Automatic light control: a wall nearer than autoLightDistance would
    // glare (inverse square), so the source is dimmed to keep it exposed.
    double intensity = m_parameters.lightIntensity;
    const double metered = distances[1];
    if (m_parameters.autoLightDistance > 0.0 && metered < m_parameters.autoLightDistance) {
        const double ratio = metered / m_parameters.autoLightDistance;
        intensity *= std::max(ratio * ratio, 0.02);
    }
    gl.Uniform1f(m_wall->uniform("uLightIntensity"), static_cast<float>(intensity));
    gl.Uniform1f(m_wall->uniform("uSpotExponent"), static_cast<float>(m_parameters.spotExponent));
    gl.Uniform1f(m_wall->uniform("uSpecular"), static_cast<float>(m_parameters.specular));
    gl.Uniform1f(m_wall->uniform("uBumpDepth"), static_cast<float>(m_parameters.bumpDepth));
    gl.Uniform1f(m_wall->uniform("uFluidAttenuation"), static_cast<float>(m_parameters.fluidAttenuation));
    const Eigen::Vector3f up = m_up.cast<float>();
    gl.Uniform3f(m_wall->uniform("uUp"), up.x(), up.y(), up.z());
    gl.Uniform1i(m_wall->uniform("uBleedingCount"), static_cast<GLint>(m_marks.size()));
    if (!m_marks.empty()) {
        gl.Uniform4fv(m_wall->uniform("uBleeding"), static_cast<GLsizei>(m_marks.size()),
                      m_markUniforms.data());
    }
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, m_mucosa);
    gl.Uniform1i(m_wall->uniform("uMucosa"), 1);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindVertexArray(m_vao);
    // Draw the chunks that may reach the image, each at the coarsest level
    // whose error stays within levelOfDetailError pixels (TubeLevelsOfDetail.h).
    const double coneAngle = 1.05 * m_parameters.fieldOfView / 2.0;  // the clip distance of Shaders.h
    const int numChunks = m_levels.numChunks();
    m_chunkNearest.resize(static_cast<size_t>(numChunks));
    for (int c = 0; c < numChunks; ++c) {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
        Eigen::Vector3d hi = -lo;
        for (int v : m_levels.chunkVertices(c)) {
            lo = lo.cwiseMin(m_positions.col(v));
            hi = hi.cwiseMax(m_positions.col(v));
        }
        const Eigen::Vector3d centre = (lo + hi) / 2.0;
        const double radius = (hi - lo).norm() / 2.0;
        const Eigen::Vector3d offset = centre - pose.position;
        const double distance = offset.norm();
        bool visible = distance - radius < m_parameters.farDistance;
        if (visible && distance > radius) {
            const double angle = std::acos(std::clamp(offset.dot(forward) / distance, -1.0, 1.0));
            visible = angle - std::asin(radius / distance) < coneAngle;
        }
        m_chunkNearest[static_cast<size_t>(c)] = visible ? std::max(distance - radius, 0.0) : -1.0;
    }
    // The fisheye is equidistant and its image circle fills the height.
    const double pixelAngle = m_parameters.fieldOfView / static_cast<double>(height);
    m_drawnTriangles = 0;
    for (const TubeLevelsOfDetail::Range& range :
         m_levels.drawList(m_chunkNearest, m_parameters.levelOfDetailError * pixelAngle)) {
        m_drawnTriangles += range.count / 3;
        gl.DrawElements(GL_TRIANGLES, range.count, GL_UNSIGNED_INT,
                        reinterpret_cast<void*>(static_cast<size_t>(range.first) * sizeof(GLuint)));
    }
    gl.Disable(GL_CLIP_DISTANCE0);
    gl.Disable(GL_DEPTH_TEST);

    const bool soiled = lens.soiling > 0.0;
    const bool clean = !soiled && m_redOut <= 0.0;
    if (soiled) {
        updateLensMask(lens, width, height);
    }
    const double blurRadius = kSoilingBlurRadius * static_cast<double>(height);  // pixels
    if (soiled) {
        reduceForBlur(blurRadius, width, height);
    }

    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.Viewport(0, 0, width, height);
    const ShaderProgram& lensPass = clean ? *m_cleanLens : *m_lens;
    lensPass.use();
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, m_targetColour);
    gl.Uniform1i(lensPass.uniform("uScene"), 0);
    gl.Uniform2f(lensPass.uniform("uTexel"), 1.0F / static_cast<float>(width),
                 1.0F / static_cast<float>(height));
    gl.Uniform1f(lensPass.uniform("uAspect"), static_cast<float>(aspect));
    gl.Uniform1f(lensPass.uniform("uRedOut"), static_cast<float>(m_redOut));
    if (!clean) {
        gl.ActiveTexture(GL_TEXTURE1);
        gl.BindTexture(GL_TEXTURE_2D, m_mask.texture);
        gl.Uniform1i(lensPass.uniform("uMask"), 1);
        gl.ActiveTexture(GL_TEXTURE2);
        gl.BindTexture(GL_TEXTURE_2D, m_blur.texture);
        gl.Uniform1i(lensPass.uniform("uBlur"), 2);
        gl.Uniform1f(lensPass.uniform("uSoiled"), soiled ? 1.0F : 0.0F);
        gl.Uniform1f(lensPass.uniform("uBlurRadius"), static_cast<float>(blurRadius));
        gl.ActiveTexture(GL_TEXTURE0);
    }
    drawScreenTriangle();
}

}  // namespace colonosim::render
