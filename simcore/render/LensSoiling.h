#pragma once
/// \file
/// Lens soiling and lens wash. The soiled fraction s of the lens (0 clean,
/// 1 covered) follows
///     ds/dt = k_s (1 - s)   while the lens is within contactDistance of the wall,
///     ds/dt = -k_w s        while the water jet (lens wash) runs,
/// and stays put otherwise: mucus and stool smear the lens on contact and
/// only a wash removes them. Integrated exactly over each step, so any step
/// keeps s in [0, 1]. k_s = soilingRate, k_w = washRate (RenderParameters).

#include "simcore/render/RenderParameters.h"

namespace colonosim::render {

class LensSoiling {
public:
    /// Throws ParameterError for invalid parameters.
    explicit LensSoiling(const RenderParameters& parameters);

    /// Advances by `dt` seconds with the lens `lensWallDistance` (m) from the
    /// wall and the lens wash on or off.
    void update(double dt, double lensWallDistance, bool washing);
    [[nodiscard]] double amount() const { return m_amount; }

private:
    RenderParameters m_parameters;
    double m_amount = 0.0;
};

}  // namespace colonosim::render
