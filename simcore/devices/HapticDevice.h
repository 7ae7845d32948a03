#pragma once
/// \file
/// What the HDC drives: a device it reads and applies force to, once per
/// servo tick. The simulated device stands in for hardware in CI.

#include "simcore/devices/ForceServo.h"
#include "simcore/procedure/DeviceInput.h"

#include <functional>
#include <span>
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
        static constexpr params::ParameterSpec massSpec{
            "carriageMass",
            "kg",
            0.3,
            0.01,
            10.0,
            "moving mass of the simulated device's linear carriage",
            "assumption: a light linear stage"};
        static constexpr params::ParameterSpec dampingSpec{"carriageDamping",
                                                           "N*s/m",
                                                           2.0,
                                                           0.0,
                                                           100.0,
                                                           "viscous friction of the carriage",
                                                           "assumption: a lightly damped linear bearing"};
        static constexpr params::ParameterSpec inertiaSpec{
            "rotorInertia",
            "kg*m^2",
            2e-4,
            1e-6,
            1e-1,
            "inertia of the simulated device's shaft rotor",
            "assumption: a short shaft section with its encoder"};
        static constexpr params::ParameterSpec rotorDampingSpec{
            "rotorDamping",
            "N*m*s/rad",
            2e-3,
            0.0,
            1.0,
            "viscous friction of the rotor",
            "assumption: a lightly damped rotary bearing"};
        static constexpr params::ParameterSpec handStiffnessSpec{
            "handStiffness",
            "N/m",
            800.0,
            1.0,
            1e4,
            "stiffness of the virtual hand's grip along the shaft",
            "assumption: a relaxed grip, a few hundred N/m (stable at 1 kHz with the carriage mass)"};
        static constexpr params::ParameterSpec handDampingSpec{
            "handDamping",
            "N*s/m",
            20.0,
            0.0,
            200.0,
            "damping of the virtual hand along the shaft",
            "assumption: near critical damping of the grip on the carriage"};
        static constexpr params::ParameterSpec torsionStiffnessSpec{
            "handTorsionStiffness",
            "N*m/rad",
            2.0,
            0.01,
            50.0,
            "torsional stiffness of the virtual hand's grip",
            "assumption: fingers twisting the shaft"};
        static constexpr params::ParameterSpec torsionDampingSpec{
            "handTorsionDamping",
            "N*m*s/rad",
            0.05,
            0.0,
            1.0,
            "torsional damping of the virtual hand",
            "assumption: near critical damping of the grip on the rotor"};

        double carriageMass = massSpec.defaultValue;
        double carriageDamping = dampingSpec.defaultValue;
        double rotorInertia = inertiaSpec.defaultValue;
        double rotorDamping = rotorDampingSpec.defaultValue;
        double handStiffness = handStiffnessSpec.defaultValue;
        double handDamping = handDampingSpec.defaultValue;
        double handTorsionStiffness = torsionStiffnessSpec.defaultValue;
        double handTorsionDamping = torsionDampingSpec.defaultValue;

        [[nodiscard]] static std::span<const params::Field<Parameters>> fields();
        void validate() const { params::validateFields("simulatedDevice", fields(), *this); }
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
