#pragma once
/// \file
/// Plain input devices for trainees without a haptic device: keyboard and
/// mouse (in the trainer) and a gamepad (SDL2's game-controller API). Both
/// give rate controls, which this integrates at the loop step into the
/// absolute input the procedure loop takes: the shaft moves in and out and
/// twists at a rate, the dials turn at a rate and stay where they are left,
/// and buttons are held. The result is kept inside the declared ranges of
/// InputSample, so a plain device can never produce refused input.

#include "simcore/procedure/DeviceInput.h"

#include <span>

namespace colonosim::devices {

/// Normalised controls in [-1, 1] (buttons: bits), as a stick or keys give them.
struct ManualControls {
    double insert = 0.0;     ///< + pushes in
    double twist = 0.0;      ///< + counter-clockwise seen from the operator
    double upDown = 0.0;     ///< + tip up
    double leftRight = 0.0;  ///< + tip left
    std::uint8_t buttons = 0;
};

struct ManualRates {
    static constexpr params::ParameterSpec insertionSpec{"insertionRate",
                                                         "m/s",
                                                         0.05,
                                                         0.005,
                                                         0.5,
                                                         "shaft feed at full deflection of a plain device",
                                                         "assumption: a brisk hand feed of about 5 cm/s"};
    static constexpr params::ParameterSpec rotationSpec{"rotationRate",
                                                        "rad/s",
                                                        1.5,
                                                        0.1,
                                                        10.0,
                                                        "shaft twist at full deflection of a plain device",
                                                        "assumption: about a quarter turn in 1 s"};
    static constexpr params::ParameterSpec dialSpec{"dialRate",
                                                    "rad/s",
                                                    2.0,
                                                    0.1,
                                                    20.0,
                                                    "dial turning rate at full deflection of a plain device",
                                                    "assumption: full dial travel in under 2 s"};
    static constexpr params::ParameterSpec deadZoneSpec{
        "deadZone",
        "1",
        0.08,
        0.0,
        0.5,
        "share of full deflection ignored around a stick's centre",
        "assumption: covers the drift of worn gamepad sticks"};

    double insertion = insertionSpec.defaultValue;  ///< m/s
    double rotation = rotationSpec.defaultValue;    ///< rad/s
    double dial = dialSpec.defaultValue;            ///< rad/s
    double deadZone = deadZoneSpec.defaultValue;    ///< 1

    [[nodiscard]] static std::span<const params::Field<ManualRates>> fields();
    void validate() const { params::validateFields("manual", fields(), *this); }
};

class ManualInput {
public:
    explicit ManualInput(const ManualRates& rates = {}) : m_rates(rates) { m_rates.validate(); }
    /// Integrates `controls` over `dt` (s); returns the new input.
    const procedure::InputSample& update(const ManualControls& controls, double dt);
    [[nodiscard]] const procedure::InputSample& input() const { return m_input; }

private:
    ManualRates m_rates;
    procedure::InputSample m_input;
};

}  // namespace colonosim::devices
