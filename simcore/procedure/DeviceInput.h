#pragma once
/// \file
/// What a person's hands do at one instant of the procedure loop: the
/// colonoscope's insertion length and shaft rotation at the anus, the two tip
/// dials, and the buttons. Every input device (keyboard, gamepad, haptic
/// device controller, scripted operator) produces these samples, and the
/// input trace records them at the loop rate.
///
/// Values are validated at the device boundary (validateInput): a non-finite
/// or out-of-range value is refused with the field, the value and the allowed
/// range, and the loop keeps the last valid sample.

#include "simcore/params/Parameter.h"

#include <cstdint>
#include <string>

namespace colonosim::procedure {

enum Button : std::uint8_t {
    kAir = 1U << 0,         ///< insufflate
    kWater = 1U << 1,       ///< water jet / lens wash
    kSuction = 1U << 2,     ///< suction
    kMarkLesion = 1U << 3,  ///< the trainee declares a finding
};

struct InputSample {
    static constexpr params::ParameterSpec insertionSpec{
        "insertion",
        "m",
        0.0,
        0.0,
        2.0,
        "length of colonoscope inserted past the anal verge",
        "working length of adult colonoscopes 1.3-1.7 m (reference table)"};
    static constexpr params::ParameterSpec rotationSpec{
        "rotation",
        "rad",
        0.0,
        -100.0,
        100.0,
        "shaft rotation at the handle, counter-clockwise seen from the operator",
        "about 16 turns either way; beyond it a device reading is taken as broken"};
    static constexpr params::ParameterSpec dialSpec{
        "dial",
        "rad",
        0.0,
        -3.5,
        3.5,
        "tip dial angle (up/down or left/right), before the scope's own clamp",
        "nominal maximum angulation 180 deg (Rozeboom et al. 2016), with margin"};

    double insertion = 0.0;      ///< m
    double rotation = 0.0;       ///< rad
    double dialUpDown = 0.0;     ///< rad, up positive
    double dialLeftRight = 0.0;  ///< rad, left positive
    std::uint8_t buttons = 0;    ///< Button bits

    friend bool operator==(const InputSample&, const InputSample&) = default;
};

/// Empty when the sample is acceptable; otherwise the reason, naming the
/// field, the value and the allowed range.
[[nodiscard]] std::string validateInput(const InputSample& sample);

}  // namespace colonosim::procedure
