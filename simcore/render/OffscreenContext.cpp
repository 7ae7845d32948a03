#include "simcore/render/OffscreenContext.h"

#include <GL/osmesa.h>

#include <cstring>

namespace colonosim::render {

struct OffscreenContext::Handle {
    OSMesaContext context = nullptr;
};

OffscreenContext::OffscreenContext(int width, int height) : m_handle(std::make_unique<Handle>())
{
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    m_handle->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (m_handle->context == nullptr) {
        throw RenderError("OSMesa could not create an OpenGL 3.3 core context");
    }
    makeCurrent(width, height);
    m_gl = std::make_unique<GlFunctions>(getProcAddress());
}

OffscreenContext::~OffscreenContext()
{
    if (m_handle->context != nullptr) {
        OSMesaDestroyContext(m_handle->context);
    }
}

void OffscreenContext::makeCurrent(int width, int height)
{
    if (width < 1 || height < 1 || width > 8192 || height > 8192) {
        throw RenderError("offscreen size " + std::to_string(width) + "x" + std::to_string(height) +
                          " is outside 1x1 to 8192x8192");
    }
    m_width = width;
    m_height = height;
    m_buffer.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 0);
    if (OSMesaMakeCurrent(m_handle->context, m_buffer.data(), GL_UNSIGNED_BYTE, width, height) == 0) {
        throw RenderError("OSMesaMakeCurrent failed");
    }
}

GetProcAddress OffscreenContext::getProcAddress() const
{
    return [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); };
}

RgbaImage OffscreenContext::readBack() const
{
    m_gl->Finish();
    RgbaImage image;
    image.width = m_width;
    image.height = m_height;
    image.pixels.resize(m_buffer.size());
    const size_t row = static_cast<size_t>(m_width) * 4;
    // OSMesa's buffer holds the bottom row first.
    for (int y = 0; y < m_height; ++y) {
        std::memcpy(image.pixels.data() + static_cast<size_t>(y) * row,
                    m_buffer.data() + static_cast<size_t>(m_height - 1 - y) * row, row);
    }
    return image;
}

}  // namespace colonosim::render
