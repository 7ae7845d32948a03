#pragma once
// Anatomy parameters with the eight segment lengths set, rectum to cecum (m).

#include "simcore/geometry/AnatomyParameters.h"

#include <array>

namespace colonosim::geometry::testing {

inline AnatomyParameters withLengths(const std::array<double, kNumSegments>& l)
{
    AnatomyParameters p;
    p.rectumLength = l[0];
    p.sigmoidLength = l[1];
    p.descendingLength = l[2];
    p.splenicFlexureLength = l[3];
    p.transverseLength = l[4];
    p.hepaticFlexureLength = l[5];
    p.ascendingLength = l[6];
    p.cecumLength = l[7];
    return p;
}

}  // namespace colonosim::geometry::testing
