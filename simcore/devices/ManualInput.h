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
    double insertion = 0.05;  ///< m/s at full deflection (assumption: a brisk hand feed, 5 cm/s)
    double rotation = 1.5;    ///< rad/s at full deflection (assumption: a quarter turn in 1 s)
    double dial = 2.0;        ///< rad/s at full deflection (assumption: full dial travel in under 2 s)
    double deadZone = 0.08;   ///< of full deflection, ignored (stick drift)
};

class ManualInput {
public:
    explicit ManualInput(const ManualRates& rates = {}) : m_rates(rates) {}
    /// Integrates `controls` over `dt` (s); returns the new input.
    const procedure::InputSample& update(const ManualControls& controls, double dt);
    [[nodiscard]] const procedure::InputSample& input() const { return m_input; }

private:
    ManualRates m_rates;
    procedure::InputSample m_input;
};

}  // namespace colonosim::devices
