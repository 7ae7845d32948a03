#pragma once
/// \file
/// A gamepad through SDL2's game-controller API (the standard mapping, so
/// any controller SDL knows works the same): left stick up/down pushes the
/// shaft in/out, left stick left/right twists it, the right stick turns the
/// dials; A air, B water (lens wash), X suction, Y marks a lesion. Its
/// controls go through ManualInput, so the procedure loop sees the same
/// InputSample as from any other device.

#include "simcore/devices/ManualInput.h"
#include "simcore/procedure/Operator.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace colonosim::devices {

class DeviceError : public std::runtime_error {
public:
    explicit DeviceError(const std::string& message) : std::runtime_error(message) {}
};

/// Raw stick and button state of a standard-mapping controller.
struct GamepadState {
    double leftX = 0.0, leftY = 0.0, rightX = 0.0, rightY = 0.0;  ///< [-1, 1], SDL's sign (+y is down)
    bool a = false, b = false, x = false, y = false;
};

/// The mapping from a controller's state to manual controls.
[[nodiscard]] ManualControls controlsFrom(const GamepadState& state);

class Gamepad {
public:
    /// Opens game controller `index`. Throws DeviceError naming what was found
    /// (no controller, SDL unavailable, index out of range).
    explicit Gamepad(int index = 0);
    ~Gamepad();
    Gamepad(const Gamepad&) = delete;
    Gamepad& operator=(const Gamepad&) = delete;

    [[nodiscard]] GamepadState read();
    [[nodiscard]] const std::string& name() const { return m_name; }

private:
    void* m_controller = nullptr;  ///< SDL_GameController*
    std::string m_name;
};

class GamepadOperator final : public procedure::Operator {
public:
    explicit GamepadOperator(int index = 0, const ManualRates& rates = {}) : m_pad(index), m_input(rates) {}
    procedure::InputSample next(const procedure::ProcedureLoop& loop) override;
    [[nodiscard]] bool finished() const override { return false; }
    [[nodiscard]] const std::string& name() const { return m_pad.name(); }

private:
    Gamepad m_pad;
    ManualInput m_input;
};

}  // namespace colonosim::devices
