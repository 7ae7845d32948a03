#include "simcore/devices/ManualInput.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace colonosim::devices {

std::span<const params::Field<ManualRates>> ManualRates::fields()
{
    static constexpr std::array<params::Field<ManualRates>, 4> kFields{{
        {&insertionSpec, &ManualRates::insertion},
        {&rotationSpec, &ManualRates::rotation},
        {&dialSpec, &ManualRates::dial},
        {&deadZoneSpec, &ManualRates::deadZone},
    }};
    return kFields;
}

namespace {
double shaped(double value, double deadZone)
{
    if (!std::isfinite(value)) {
        return 0.0;  // a broken axis reading moves nothing
    }
    const double v = std::clamp(value, -1.0, 1.0);
    const double magnitude = std::abs(v);
    return magnitude <= deadZone ? 0.0 : std::copysign((magnitude - deadZone) / (1.0 - deadZone), v);
}

double within(double value, const params::ParameterSpec& spec)
{
    return std::clamp(value, spec.minValue, spec.maxValue);
}
}  // namespace

const procedure::InputSample& ManualInput::update(const ManualControls& c, double dt)
{
    using procedure::InputSample;
    const double d = m_rates.deadZone;
    m_input.insertion =
        within(m_input.insertion + dt * m_rates.insertion * shaped(c.insert, d), InputSample::insertionSpec);
    m_input.rotation =
        within(m_input.rotation + dt * m_rates.rotation * shaped(c.twist, d), InputSample::rotationSpec);
    m_input.dialUpDown =
        within(m_input.dialUpDown + dt * m_rates.dial * shaped(c.upDown, d), InputSample::dialSpec);
    m_input.dialLeftRight =
        within(m_input.dialLeftRight + dt * m_rates.dial * shaped(c.leftRight, d), InputSample::dialSpec);
    m_input.buttons = static_cast<std::uint8_t>(
        c.buttons & (procedure::kAir | procedure::kWater | procedure::kSuction | procedure::kMarkLesion));
    return m_input;
}

}  // namespace colonosim::devices
