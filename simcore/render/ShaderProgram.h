#pragma once
/// \file
/// A linked GLSL 330 core program built from source parts (Shaders.h).

#include "simcore/render/GlFunctions.h"

#include <initializer_list>

namespace colonosim::render {

class ShaderProgram {
public:
    /// Compiles "#version 330 core" followed by the parts of each stage and
    /// links them; throws RenderError with the compiler's log.
    ShaderProgram(const GlFunctions& gl, std::initializer_list<const char*> vertexParts,
                  std::initializer_list<const char*> fragmentParts);
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { m_gl.UseProgram(m_program); }
    /// Location of a uniform (-1 when the compiler removed it).
    [[nodiscard]] GLint uniform(const char* name) const { return m_gl.GetUniformLocation(m_program, name); }

private:
    const GlFunctions& m_gl;
    GLuint m_program = 0;
};

}  // namespace colonosim::render
