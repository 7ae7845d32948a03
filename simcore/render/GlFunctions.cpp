#include "simcore/render/GlFunctions.h"

#include <cstdio>

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

}  // namespace colonosim::render
