#include "simcore/render/ShaderProgram.h"

#include <string>
#include <vector>

namespace colonosim::render {

namespace {
GLuint compile(const GlFunctions& gl, GLenum stage, std::initializer_list<const char*> parts)
{
    std::vector<const char*> sources{"#version 330 core\n"};
    sources.insert(sources.end(), parts.begin(), parts.end());
    const GLuint shader = gl.CreateShader(stage);
    gl.ShaderSource(shader, static_cast<GLsizei>(sources.size()), sources.data(), nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == 0) {
        std::string log(4096, '\0');
        GLsizei length = 0;
        gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), &length, log.data());
        gl.DeleteShader(shader);
        log.resize(static_cast<size_t>(length));
        throw RenderError(std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                          " shader does not compile: " + log);
    }
    return shader;
}
}  // namespace

ShaderProgram::ShaderProgram(const GlFunctions& gl, std::initializer_list<const char*> vertexParts,
                             std::initializer_list<const char*> fragmentParts)
    : m_gl(gl)
{
    const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertexParts);
    const GLuint fragment = compile(gl, GL_FRAGMENT_SHADER, fragmentParts);
    m_program = gl.CreateProgram();
    gl.AttachShader(m_program, vertex);
    gl.AttachShader(m_program, fragment);
    gl.LinkProgram(m_program);
    gl.DeleteShader(vertex);
    gl.DeleteShader(fragment);
    GLint ok = 0;
    gl.GetProgramiv(m_program, GL_LINK_STATUS, &ok);
    if (ok == 0) {
        std::string log(4096, '\0');
        GLsizei length = 0;
        gl.GetProgramInfoLog(m_program, static_cast<GLsizei>(log.size()), &length, log.data());
        log.resize(static_cast<size_t>(length));
        gl.DeleteProgram(m_program);
        throw RenderError("shader program does not link: " + log);
    }
}

ShaderProgram::~ShaderProgram()
{
    m_gl.DeleteProgram(m_program);
}

}  // namespace colonosim::render
