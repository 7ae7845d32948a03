#pragma once
/// \file
/// The largest tensile strain (l - L) / L over a set of springs or tethers,
/// as the loop reads it every step (the wall's stress, the mesentery's
/// stretch), without a square root and a division for each of them.
///
/// The strain rises with the squared stretch (l / L)^2, which needs
/// neither: the largest squared stretch is found first, then the strain
/// itself is taken only of the members within 1e-12 of it. Rounding moves
/// the squared stretch by about 1e-15 of itself, so the member of largest
/// strain is among them, and the result is the strain formula's over every
/// member, bit for bit: 0 when none is stretched.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace colonosim::physics {

/// `stretch2(e)`: member e's (l / L)^2; `strain(e)`: its (l - L) / L, as
/// the caller defines it; `scratch` keeps the squared stretches between the
/// two passes (resized to `count`).
template <class Stretch2, class Strain>
double largestTensileStrain(std::size_t count, std::vector<double>& scratch, Stretch2&& stretch2,
                            Strain&& strain)
{
    scratch.resize(count);
    double most = 0.0;
    for (std::size_t e = 0; e < count; ++e) {
        scratch[e] = stretch2(e);
        most = std::max(most, scratch[e]);
    }
    constexpr double kWithin = 1e-12;
    if (!(most >= 1.0 - kWithin)) {
        return 0.0;  // none stretched (and no strain above 0 within rounding)
    }
    const double candidate = most * (1.0 - kWithin);
    double largest = 0.0;
    for (std::size_t e = 0; e < count; ++e) {
        if (scratch[e] >= candidate) {
            largest = std::max(largest, strain(e));
        }
    }
    return largest;
}

}  // namespace colonosim::physics
