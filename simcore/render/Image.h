#pragma once
/// \file
/// An RGBA8 image in memory, top row first, as the renderer hands it out.

#include <cstdint>
#include <vector>

namespace colonosim::render {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  ///< width * height * 4 bytes, rows top to bottom

    [[nodiscard]] const std::uint8_t* at(int x, int y) const
    {
        return pixels.data() +
               (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4;
    }
};

}  // namespace colonosim::render
