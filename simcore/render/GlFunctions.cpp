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

void allocateColourDepthTarget(const GlFunctions& gl, GLuint& framebuffer, GLuint& colour, GLuint& depth,
                               int width, int height, GLint filter, const char* what)
{
    if (framebuffer == 0) {
        gl.GenFramebuffers(1, &framebuffer);
        gl.GenTextures(1, &colour);
        gl.GenRenderbuffers(1, &depth);
    }
    gl.BindTexture(GL_TEXTURE_2D, colour);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw RenderError(what);
    }
}

}  // namespace colonosim::render
