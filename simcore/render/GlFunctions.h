#pragma once
/// \file
/// The OpenGL 3.3 core entry points the renderer uses, loaded through the
/// host context's own getProcAddress (OSMesaGetProcAddress headless, the Qt
/// context's in the trainer). Nothing is taken from the link: with glvnd's
/// libOpenGL and libOSMesa both in a process, link order would decide which
/// implementation a direct call reaches.

#include <GL/glcorearb.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace colonosim::render {

/// Thrown when a context, shader or framebuffer cannot be made.
class RenderError : public std::runtime_error {
public:
    explicit RenderError(const std::string& message) : std::runtime_error(message) {}
};

/// Returns the address of a GL entry point by name, or null.
using GetProcAddress = std::function<void*(const char* name)>;

// X-macro: type of the function pointer, name without the "gl" prefix.
#define COLONOSIM_GL_FUNCTIONS(X)                                                                            \
    X(PFNGLGETSTRINGPROC, GetString)                                                                         \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                                     \
    X(PFNGLGETERRORPROC, GetError)                                                                           \
    X(PFNGLVIEWPORTPROC, Viewport)                                                                           \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                                                       \
    X(PFNGLCLEARPROC, Clear)                                                                                 \
    X(PFNGLENABLEPROC, Enable)                                                                               \
    X(PFNGLDISABLEPROC, Disable)                                                                             \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                                         \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                                                                         \
    X(PFNGLFINISHPROC, Finish)                                                                               \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                                     \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                                       \
    X(PFNGLCREATESHADERPROC, CreateShader)                                                                   \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                                   \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                                                 \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                                     \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                                           \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                                                   \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                                 \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                                                   \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                                     \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                                   \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                         \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                                 \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                                       \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                                       \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                                                         \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                                                         \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                                                         \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                                                         \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                                                         \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                                       \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                                           \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                             \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                             \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                                       \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                                       \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                                       \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                                       \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                                                 \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                                 \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                                     \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                             \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                                   \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                                       \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                             \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                             \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                                   \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                                             \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                               \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                                       \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                                           \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                                           \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                                                     \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                                                     \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                                                     \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                                                     \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                                       \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                                 \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                               \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                                 \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)

/// The function-pointer table. Member names drop the "gl" prefix:
/// gl.Clear(GL_COLOR_BUFFER_BIT).
struct GlFunctions {
#define COLONOSIM_GL_MEMBER(type, name) type name = nullptr;
    COLONOSIM_GL_FUNCTIONS(COLONOSIM_GL_MEMBER)
#undef COLONOSIM_GL_MEMBER

    /// Loads every entry point; throws RenderError naming the first missing
    /// one, or when the context is older than OpenGL 3.3.
    explicit GlFunctions(const GetProcAddress& getProcAddress);
};

/// An offscreen render target: a colour texture (`filter` for minification and
/// magnification, clamped at the edges) and a 24-bit depth renderbuffer on one
/// framebuffer. The objects are generated on the first call (`framebuffer` is
/// 0), then only their storage is reallocated. Leaves the framebuffer bound;
/// throws RenderError naming `what` when it is incomplete.
void allocateColourDepthTarget(const GlFunctions& gl, GLuint& framebuffer, GLuint& colour, GLuint& depth,
                               int width, int height, GLint filter, const char* what);

/// The same without depth, the texture of `internalFormat` (GL_RGBA8,
/// GL_R8, ...).
void allocateColourTarget(const GlFunctions& gl, GLuint& framebuffer, GLuint& colour, int width, int height,
                          GLint internalFormat, GLint filter, const char* what);

/// A colour-only render target whose storage follows the size it is bound at.
struct ColourTarget {
    GLuint framebuffer = 0;
    GLuint texture = 0;
    int width = 0;   ///< pixels, 0 before the first bind
    int height = 0;  ///< pixels

    /// Reallocates the storage (allocateColourTarget) when width x height
    /// differs from the last, then binds the framebuffer and sets the viewport.
    void bind(const GlFunctions& gl, int w, int h, GLint internalFormat, GLint filter, const char* what);
    /// Deletes the objects (with the context current).
    void release(const GlFunctions& gl);
};

}  // namespace colonosim::render
