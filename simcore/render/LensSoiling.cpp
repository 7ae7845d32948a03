#include "simcore/render/LensSoiling.h"

#include <algorithm>
#include <cmath>

namespace colonosim::render {

LensSoiling::LensSoiling(const RenderParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
}

void LensSoiling::update(double dt, double lensWallDistance, bool washing)
{
    if (!(dt > 0.0)) {
        return;
    }
    if (washing) {
        m_amount *= std::exp(-m_parameters.washRate * dt);
    } else if (lensWallDistance <= m_parameters.contactDistance) {
        m_amount = 1.0 - (1.0 - m_amount) * std::exp(-m_parameters.soilingRate * dt);
    }
    m_amount = std::clamp(m_amount, 0.0, 1.0);
}

}  // namespace colonosim::render
