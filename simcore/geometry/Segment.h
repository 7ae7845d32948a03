#pragma once
/// \file
/// The anatomical segments of the colon, anus to cecum, and how each is held.

#include <cstdint>
#include <string_view>

namespace colonosim::geometry {

enum class Segment : std::uint8_t {
    Rectum,
    Sigmoid,
    Descending,
    SplenicFlexure,
    Transverse,
    HepaticFlexure,
    Ascending,
    Cecum,
};
inline constexpr int kNumSegments = 8;

/// How a wall node is held by its surroundings.
enum class Attachment : std::uint8_t {
    Fixed,            ///< held at the anal canal / pelvic floor
    Retroperitoneal,  ///< bound to the posterior abdominal wall (anchored)
    Mesenteric,       ///< mobile, hung on a mesentery
};

[[nodiscard]] std::string_view segmentName(Segment segment);

}  // namespace colonosim::geometry
