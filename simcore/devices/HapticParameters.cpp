#include "simcore/devices/HapticParameters.h"

#include <array>

namespace colonosim::devices {

std::span<const Field<HapticParameters>> HapticParameters::fields()
{
    static constexpr std::array<Field<HapticParameters>, 8> kFields{{
        {&maxForceSpec, &HapticParameters::maxForce},
        {&maxTorqueSpec, &HapticParameters::maxTorque},
        {&forceRateSpec, &HapticParameters::forceRateLimit},
        {&torqueRateSpec, &HapticParameters::torqueRateLimit},
        {&servoPeriodSpec, &HapticParameters::servoPeriod},
        {&watchdogSpec, &HapticParameters::watchdogTimeout},
        {&extrapolationSpec, &HapticParameters::extrapolationHorizon},
        {&maxMessageSpec, &HapticParameters::maxMessageBytes},
    }};
    return kFields;
}

void HapticParameters::validate() const
{
    params::validateFields("haptics", fields(), *this);
}

}  // namespace colonosim::devices
