#include "simcore/render/GlFunctions.h"

namespace colonosim::render {

GlFunctions::GlFunctions(const GetProcAddress& getProcAddress)
{
#define COLONOSIM_GL_LOAD(type, name)                                                                        \
    name = reinterpret_cast<type>(getProcAddress("gl" #name));                                               \
    if (name == nullptr) {                                                                                   \
        throw RenderError("OpenGL entry point gl" #name " is not available");                                \
    }
    COLONOSIM_GL_FUNCTIONS(COLONOSIM_GL_LOAD)
#undef COLONOSIM_GL_LOAD
    GLint major = 0;
    GLint minor = 0;
    GetIntegerv(GL_MAJOR_VERSION, &major);
    GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 33) {
        throw RenderError("OpenGL 3.3 core is required; the context gives " + std::to_string(major) + "." +
                          std::to_string(minor));
    }
}

namespace {

/// Generates `colour` on the first call and gives it width x height texels of
/// `internalFormat`, filtered by `filter`, clamped at the edges.
void allocateColourTexture(const GlFunctions& gl, GLuint& colour, int width, int height, GLint internalFormat,
                           GLint filter)
{
    if (colour == 0) {
        gl.GenTextures(1, &colour);
    }
    const GLenum format = internalFormat == GL_R8 ? GL_RED : GL_RGBA;
    gl.BindTexture(GL_TEXTURE_2D, colour);
    gl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, GL_UNSIGNED_BYTE, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void checkComplete(const GlFunctions& gl, const char* what)
{
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw RenderError(what);
    }
}

}  // namespace

void allocateColourDepthTarget(const GlFunctions& gl, GLuint& framebuffer, GLuint& colour, GLuint& depth,
                               int width, int height, GLint filter, const char* what)
{
    if (framebuffer == 0) {
        gl.GenFramebuffers(1, &framebuffer);
        gl.GenRenderbuffers(1, &depth);
    }
    allocateColourTexture(gl, colour, width, height, GL_RGBA8, filter);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    checkComplete(gl, what);
}

void allocateColourTarget(const GlFunctions& gl, GLuint& framebuffer, GLuint& colour, int width, int height,
                          GLint internalFormat, GLint filter, const char* what)
{
    if (framebuffer == 0) {
        gl.GenFramebuffers(1, &framebuffer);
    }
    allocateColourTexture(gl, colour, width, height, internalFormat, filter);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    checkComplete(gl, what);
}

void ColourTarget::bind(const GlFunctions& gl, int w, int h, GLint internalFormat, GLint filter,
                        const char* what)
{
    if (w != width || h != height) {
        allocateColourTarget(gl, framebuffer, texture, w, h, internalFormat, filter, what);
        width = w;
        height = h;
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.Viewport(0, 0, w, h);
}

void ColourTarget::release(const GlFunctions& gl)
{
    gl.DeleteTextures(1, &texture);
    gl.DeleteFramebuffers(1, &framebuffer);
}

}  // namespace colonosim::render
