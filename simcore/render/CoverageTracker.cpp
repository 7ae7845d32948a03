#include "simcore/render/CoverageTracker.h"

#include "simcore/render/Shaders.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colonosim::render {

CoverageTracker::CoverageTracker(const GlFunctions& gl, const geometry::TriangleMesh& restMesh,
                                 std::vector<geometry::Segment> triangleSegment,
                                 const RenderParameters& parameters)
    : m_gl(gl), m_parameters(parameters), m_segment(std::move(triangleSegment))
{
    m_parameters.validate();
    if (static_cast<int>(m_segment.size()) != restMesh.numTriangles()) {
        throw std::invalid_argument("CoverageTracker: one segment per triangle is needed");
    }
    m_program = std::make_unique<ShaderProgram>(
        gl, std::initializer_list<const char*>{shaders::kFisheye, shaders::kCoverageVertex},
        std::initializer_list<const char*>{shaders::kCoverageFragment});
    m_size = static_cast<int>(m_parameters.coverageResolution);
    const auto numTriangles = static_cast<size_t>(restMesh.numTriangles());
    m_area.resize(numTriangles);
    m_seen.assign(numTriangles, 0);
    m_inView.assign(numTriangles, 0);
    std::vector<GLuint> indices;
    for (size_t t = 0; t < numTriangles; ++t) {
        const auto& tri = restMesh.triangles[t];
        const Eigen::Vector3d a = restMesh.vertices.col(tri[0]);
        m_area[t] = 0.5 * (restMesh.vertices.col(tri[1]) - a).cross(restMesh.vertices.col(tri[2]) - a).norm();
        m_totalArea += m_area[t];
        m_segmentArea[static_cast<size_t>(m_segment[t])] += m_area[t];
        indices.insert(indices.end(), {static_cast<GLuint>(tri[0]), static_cast<GLuint>(tri[1]),
                                       static_cast<GLuint>(tri[2])});
    }
    m_numIndices = static_cast<GLsizei>(indices.size());
    gl.GenVertexArrays(1, &m_vao);
    gl.BindVertexArray(m_vao);
    gl.GenBuffers(1, &m_positionBuffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, m_positionBuffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(restMesh.vertices.cols() * 3 * sizeof(float)),
                  nullptr, GL_STREAM_DRAW);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(0);
    gl.GenBuffers(1, &m_indexBuffer);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
                  indices.data(), GL_STATIC_DRAW);
    gl.BindVertexArray(0);

    allocateColourDepthTarget(gl, m_framebuffer, m_colour, m_depth, m_size, m_size, GL_NEAREST,
                              "the coverage ID buffer is incomplete");
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    m_pixels.resize(static_cast<size_t>(m_size) * static_cast<size_t>(m_size) * 4);
}

CoverageTracker::~CoverageTracker()
{
    m_gl.DeleteBuffers(1, &m_positionBuffer);
    m_gl.DeleteBuffers(1, &m_indexBuffer);
    m_gl.DeleteVertexArrays(1, &m_vao);
    m_gl.DeleteFramebuffers(1, &m_framebuffer);
    m_gl.DeleteTextures(1, &m_colour);
    m_gl.DeleteRenderbuffers(1, &m_depth);
}

void CoverageTracker::setLesionTriangles(std::vector<std::vector<int>> lesionTriangles)
{
    m_lesionTriangles = std::move(lesionTriangles);
    m_lesionsInView.assign(m_lesionTriangles.size(), false);
}

bool CoverageTracker::update(double time, const Eigen::Matrix3Xd& positions, const CameraPose& pose)
{
    if (time - m_lastUpdate < m_parameters.coverageInterval) {
        return false;
    }
    m_lastUpdate = time;
    observe(positions, pose);
    return true;
}

void CoverageTracker::observe(const Eigen::Matrix3Xd& positions, const CameraPose& pose)
{
    const GlFunctions& gl = m_gl;
    m_upload.resize(static_cast<size_t>(positions.cols()) * 3);
    for (Eigen::Index i = 0; i < positions.cols(); ++i) {
        for (int k = 0; k < 3; ++k) {
            m_upload[static_cast<size_t>(3 * i + k)] = static_cast<float>(positions(k, i));
        }
    }
    gl.BindBuffer(GL_ARRAY_BUFFER, m_positionBuffer);
    gl.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(m_upload.size() * sizeof(float)),
                     m_upload.data());

    gl.BindFramebuffer(GL_FRAMEBUFFER, m_framebuffer);
    gl.Viewport(0, 0, m_size, m_size);
    gl.ClearColor(0.0F, 0.0F, 0.0F, 1.0F);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_CLIP_DISTANCE0);
    m_program->use();
    const Eigen::Matrix3f w = worldToCamera(pose).cast<float>();
    gl.UniformMatrix3fv(m_program->uniform("uWorldToCamera"), 1, GL_FALSE, w.data());
    const Eigen::Vector3f p = pose.position.cast<float>();
    gl.Uniform3f(m_program->uniform("uCameraPosition"), p.x(), p.y(), p.z());
    gl.Uniform1f(m_program->uniform("uHalfFieldOfView"), static_cast<float>(m_parameters.fieldOfView / 2.0));
    gl.Uniform1f(m_program->uniform("uAspect"), 1.0F);
    gl.Uniform2f(m_program->uniform("uDepthRange"), static_cast<float>(m_parameters.nearDistance),
                 static_cast<float>(m_parameters.farDistance));
    gl.Uniform1f(m_program->uniform("uWorkingDistance"), static_cast<float>(m_parameters.workingDistance));
    gl.Uniform1f(m_program->uniform("uMinCosIncidence"),
                 static_cast<float>(std::cos(m_parameters.maxIncidence)));
    gl.BindVertexArray(m_vao);
    gl.DrawElements(GL_TRIANGLES, m_numIndices, GL_UNSIGNED_INT, nullptr);
    gl.BindVertexArray(0);
    gl.Disable(GL_CLIP_DISTANCE0);
    gl.Disable(GL_DEPTH_TEST);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, m_size, m_size, GL_RGBA, GL_UNSIGNED_BYTE, m_pixels.data());
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

    std::fill(m_inView.begin(), m_inView.end(), 0);
    const double centre = m_size / 2.0;
    for (int y = 0; y < m_size; ++y) {
        for (int x = 0; x < m_size; ++x) {
            const double dx = x + 0.5 - centre;
            const double dy = y + 0.5 - centre;
            if (dx * dx + dy * dy > centre * centre) {
                continue;  // outside the image circle
            }
            const std::uint8_t* px =
                &m_pixels[(static_cast<size_t>(y) * static_cast<size_t>(m_size) + static_cast<size_t>(x)) *
                          4];
            const int id = px[0] | (px[1] << 8) | (px[2] << 16);
            if (id > 0 && static_cast<size_t>(id) <= m_seen.size()) {
                m_seen[static_cast<size_t>(id - 1)] = 1;
                m_inView[static_cast<size_t>(id - 1)] = 1;
            }
        }
    }
    for (size_t l = 0; l < m_lesionTriangles.size(); ++l) {
        bool inView = false;
        for (int t : m_lesionTriangles[l]) {
            inView = inView || m_inView[static_cast<size_t>(t)] != 0;
        }
        m_lesionsInView[l] = inView;
    }
    ++m_numUpdates;
}

double CoverageTracker::fractionSeen() const
{
    double seen = 0.0;
    for (size_t t = 0; t < m_seen.size(); ++t) {
        seen += m_seen[t] != 0 ? m_area[t] : 0.0;
    }
    return m_totalArea > 0.0 ? seen / m_totalArea : 0.0;
}

double CoverageTracker::fractionSeen(geometry::Segment segment) const
{
    double seen = 0.0;
    for (size_t t = 0; t < m_seen.size(); ++t) {
        seen += m_seen[t] != 0 && m_segment[t] == segment ? m_area[t] : 0.0;
    }
    const double total = m_segmentArea[static_cast<size_t>(segment)];
    return total > 0.0 ? seen / total : 0.0;
}

std::vector<int> trianglesNear(const geometry::TriangleMesh& mesh, const Eigen::Vector3d& centre,
                               double radius)
{
    std::vector<int> out;
    for (int t = 0; t < mesh.numTriangles(); ++t) {
        for (int v : mesh.triangles[static_cast<size_t>(t)]) {
            if ((mesh.vertices.col(v) - centre).norm() <= radius) {
                out.push_back(t);
                break;
            }
        }
    }
    return out;
}

}  // namespace colonosim::render
