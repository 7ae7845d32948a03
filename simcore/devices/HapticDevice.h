#pragma once
/// \file
/// What the HDC drives: a device it reads and applies force to, once per
/// servo tick. The simulated device stands in for hardware in CI.

#include "simcore/devices/ForceServo.h"
#include "simcore/procedure/DeviceInput.h"

#include <functional>
#include <string>

namespace colonosim::devices {

class HapticDevice {
public:
    virtual ~HapticDevice() = default;
    /// The handle's state now (insertion, rotation, dials, buttons).
    [[nodiscard]] virtual procedure::InputSample read() const = 0;
    /// Applies `command` for one servo period `dt` (s).
    virtual void apply(const HandleCommand& command, double dt) = 0;
    [[nodiscard]] virtual std::string name() const = 0;
    [[nodiscard]] virtual bool emergencyStopPressed() const { return false; }
};

/// The hand's intended input at time t (s): a recorded trace, a script.
using HandTrajectory = std::function<procedure::InputSample(double)>;

/// A carriage of mass m on the shaft axis and a rotor of inertia J, each with
/// viscous friction, held by a virtual hand: a spring-damper that pulls them
/// towards the trajectory. The rendered handle force pushes the carriage back
/// (it resists insertion), the torque turns the rotor. Dials and buttons
/// follow the hand directly. Semi-implicit Euler at the servo period.
class SimulatedDevice final : public HapticDevice {
public:
    struct Parameters {
        double carriageMass = 0.3;          ///< kg (assumption: a light linear stage)
        double carriageDamping = 2.0;       ///< N s/m
        double rotorInertia = 2e-4;         ///< kg m^2
        double rotorDamping = 2e-3;         ///< N m s/rad
        double handStiffness = 800.0;       ///< N/m (assumption: a relaxed grip, a few hundred N/m)
        double handDamping = 20.0;          ///< N s/m
        double handTorsionStiffness = 2.0;  ///< N m/rad
        double handTorsionDamping = 0.05;   ///< N m s/rad
    };

    SimulatedDevice(HandTrajectory hand, const Parameters& parameters);
    explicit SimulatedDevice(HandTrajectory hand) : SimulatedDevice(std::move(hand), Parameters{}) {}

    [[nodiscard]] procedure::InputSample read() const override { return m_state; }
    void apply(const HandleCommand& command, double dt) override;
    [[nodiscard]] std::string name() const override { return "simulated"; }

    [[nodiscard]] double time() const { return m_time; }
    [[nodiscard]] double appliedForce() const { return m_lastForce; }

private:
    HandTrajectory m_hand;
    Parameters m_parameters;
    procedure::InputSample m_state;
    double m_velocity = 0.0, m_spin = 0.0, m_time = 0.0, m_lastForce = 0.0;
    procedure::InputSample m_previousHand;
};

}  // namespace colonosim::devices
