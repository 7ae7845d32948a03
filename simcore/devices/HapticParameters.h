#pragma once
/// \file
/// Declared parameters of the haptic side (SI; see ../params/Parameter.h):
/// the device limits the Haptic Device Controller (HDC) enforces, its servo
/// period and watchdog, and the largest network message either side accepts.

#include "simcore/params/Parameter.h"

#include <span>

namespace colonosim::devices {

using params::Field;
using params::ParameterSpec;

struct HapticParameters {
    static constexpr ParameterSpec maxForceSpec{
        "maxForce",
        "N",
        25.0,
        0.0,
        100.0,
        "largest axial force the device may apply to the operator's hand",
        "seeds/001 (CSIRO colonoscopy device: up to 25 N linear feedback)"};
    static constexpr ParameterSpec maxTorqueSpec{
        "maxTorque",
        "N*m",
        1.0,
        0.0,
        10.0,
        "largest torque about the shaft the device may apply",
        "seeds/001 (CSIRO colonoscopy device: up to 1 N m rotational feedback)"};
    static constexpr ParameterSpec forceRateSpec{
        "forceRateLimit",
        "N/s",
        5000.0,
        1.0,
        1.0e5,
        "largest rate of change of the applied force (full scale in 5 ms, so a lost link reaches zero in "
        "time)",
        "assumption: 25 N over 5 ms; below the 1 kHz servo's resolution a faster change is a step"};
    static constexpr ParameterSpec torqueRateSpec{
        "torqueRateLimit",
        "N*m/s",
        200.0,
        0.01,
        1.0e4,
        "largest rate of change of the applied torque (full scale in 5 ms)",
        "assumption: 1 N m over 5 ms"};
    static constexpr ParameterSpec servoPeriodSpec{
        "servoPeriod",
        "s",
        1.0e-3,
        1.0e-4,
        1.0e-2,
        "period of the HDC's servo loop",
        "seeds/000 (haptic rate 1 kHz, force rendering independent of the simulation's cycle)"};
    static constexpr ParameterSpec watchdogSpec{
        "watchdogTimeout",
        "s",
        0.02,
        1.0e-3,
        1.0,
        "silence from the simulator after which the force ramps to zero",
        "assumption: 20 loop periods of a 1 kHz simulator; a closed link is acted on at once"};
    static constexpr ParameterSpec extrapolationSpec{
        "extrapolationHorizon",
        "s",
        5.0e-3,
        0.0,
        0.1,
        "how far past the last simulator update the force is extrapolated before it is held",
        "assumption: a few simulator periods; beyond that the trend is not trusted"};
    static constexpr ParameterSpec maxMessageSpec{
        "maxMessageBytes",
        "B",
        4096.0,
        128.0,
        1.0e6,
        "largest OpenIGTLink message body either side accepts; a larger one closes the link",
        "assumption: our largest message (TRANSFORM) has a 48-byte body"};

    double maxForce = maxForceSpec.defaultValue;
    double maxTorque = maxTorqueSpec.defaultValue;
    double forceRateLimit = forceRateSpec.defaultValue;
    double torqueRateLimit = torqueRateSpec.defaultValue;
    double servoPeriod = servoPeriodSpec.defaultValue;
    double watchdogTimeout = watchdogSpec.defaultValue;
    double extrapolationHorizon = extrapolationSpec.defaultValue;
    double maxMessageBytes = maxMessageSpec.defaultValue;

    [[nodiscard]] static std::span<const Field<HapticParameters>> fields();
    void validate() const;
};

}  // namespace colonosim::devices
