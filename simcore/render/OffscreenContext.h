#pragma once
/// \file
/// The headless host: an OSMesa (llvmpipe) OpenGL core context, 3.3 or
/// newer, rendering into a buffer in memory. For tests, image output and
/// benchmarks on machines with no display and no GPU.

#include "simcore/render/GlFunctions.h"
#include "simcore/render/Image.h"

#include <memory>
#include <vector>

namespace colonosim::render {

class OffscreenContext {
public:
    /// Creates the context and makes it current on this thread with a
    /// width x height RGBA8 default framebuffer. Throws RenderError.
    OffscreenContext(int width, int height);
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    /// Makes the context current again (and resizes its framebuffer).
    void makeCurrent(int width, int height);
    [[nodiscard]] GetProcAddress getProcAddress() const;
    [[nodiscard]] const GlFunctions& gl() const { return *m_gl; }
    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }
    /// Waits for rendering and returns the default framebuffer, top row first.
    [[nodiscard]] RgbaImage readBack() const;

private:
    struct Handle;
    std::unique_ptr<Handle> m_handle;
    std::vector<unsigned char> m_buffer;
    std::unique_ptr<GlFunctions> m_gl;
    int m_width = 0;
    int m_height = 0;
};

}  // namespace colonosim::render
