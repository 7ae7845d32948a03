#pragma once
/// \file
/// A place on the colon's wall as a case gives it (the arc length from the
/// anus along the centreline and the clock angle in the centreline's frame),
/// and the physics node that carries it: the node nearest that wall point at
/// rest. Lesions and adhesions are placed so.

#include "simcore/geometry/ColonAnatomy.h"

#include <string>

namespace colonosim::procedure {

struct WallSite {
    double arcLength = 0.0;  ///< m from the anus along the centreline
    double angle = 0.0;      ///< rad, clock angle in the centreline's frame
};

/// The physics node nearest `site`'s wall point at rest. Throws
/// params::ParameterError naming `field` (e.g. "adhesions[2]"), the value and
/// the allowed range when the arc length lies outside the colon or the angle
/// is not finite.
[[nodiscard]] int wallNodeAt(const geometry::ColonAnatomy& anatomy, const WallSite& site,
                             const std::string& field);

}  // namespace colonosim::procedure
