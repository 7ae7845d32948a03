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
/// range, and the loop keeps the last valid sample. A valid sample is then
/// quantised to the input resolution (quantizeInput), as a device's encoders
/// would: what drives the simulation, and what the trace records, is an exact
/// multiple of a power of two, so the trace compresses well and replays bit
/// for bit.

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

/// The resolution of the input, as a device's encoders give it. Powers of two,
/// so a quantised value is exact in binary and quantising is idempotent.
struct InputResolution {
    static constexpr params::ParameterSpec insertionSpec{
        "insertionResolution",
        "m",
        7.62939453125e-6,
        7.62939453125e-6,
        7.62939453125e-6,
        "step of the recorded insertion length: 2^-17 m (7.6 um)",
        "assumption: finer than the linear encoders of haptic colonoscopy devices (tens of um); a "
        "power of two so the value is exact in binary"};
    static constexpr params::ParameterSpec angleSpec{
        "angleResolution",
        "rad",
        1.220703125e-4,
        1.220703125e-4,
        1.220703125e-4,
        "step of the recorded shaft rotation and dial angles: 2^-13 rad (0.007 deg)",
        "assumption: finer than rotary encoders of 4,096 counts per turn (1.5 mrad); a power of two "
        "so the value is exact in binary"};
};

/// `sample` with its insertion and angles rounded to the input resolution.
[[nodiscard]] InputSample quantizeInput(const InputSample& sample);

}  // namespace colonosim::procedure
