#include "simcore/devices/HapticDevice.h"

#include <algorithm>
#include <array>

namespace colonosim::devices {

std::span<const params::Field<SimulatedDevice::Parameters>> SimulatedDevice::Parameters::fields()
{
    using P = SimulatedDevice::Parameters;
    static constexpr std::array<params::Field<P>, 8> kFields{{
        {&P::massSpec, &P::carriageMass},
        {&P::dampingSpec, &P::carriageDamping},
        {&P::inertiaSpec, &P::rotorInertia},
        {&P::rotorDampingSpec, &P::rotorDamping},
        {&P::handStiffnessSpec, &P::handStiffness},
        {&P::handDampingSpec, &P::handDamping},
        {&P::torsionStiffnessSpec, &P::handTorsionStiffness},
        {&P::torsionDampingSpec, &P::handTorsionDamping},
    }};
    return kFields;
}

SimulatedDevice::SimulatedDevice(HandTrajectory hand, const Parameters& parameters)
    : m_hand(std::move(hand)), m_parameters(parameters)
{
    m_parameters.validate();
    m_state = m_hand(0.0);
    m_previousHand = m_state;
}

void SimulatedDevice::apply(const HandleCommand& command, double dt)
{
    const Parameters& p = m_parameters;
    m_time += dt;
    const procedure::InputSample hand = m_hand(m_time);
    const double handVelocity = (hand.insertion - m_previousHand.insertion) / dt;
    const double handSpin = (hand.rotation - m_previousHand.rotation) / dt;
    m_previousHand = hand;
    m_lastForce = command.force;
    // The handle force resists insertion: it pushes the carriage back.
    const double force = p.handStiffness * (hand.insertion - m_state.insertion) +
                         p.handDamping * (handVelocity - m_velocity) - p.carriageDamping * m_velocity -
                         command.force;
    m_velocity += dt * force / p.carriageMass;
    m_state.insertion = std::max(0.0, m_state.insertion + dt * m_velocity);
    if (m_state.insertion == 0.0 && m_velocity < 0.0) {
        m_velocity = 0.0;
    }
    const double torque = p.handTorsionStiffness * (hand.rotation - m_state.rotation) +
                          p.handTorsionDamping * (handSpin - m_spin) - p.rotorDamping * m_spin -
                          command.torque;
    m_spin += dt * torque / p.rotorInertia;
    m_state.rotation += dt * m_spin;
    m_state.dialUpDown = hand.dialUpDown;
    m_state.dialLeftRight = hand.dialLeftRight;
    m_state.buttons = hand.buttons;
}

}  // namespace colonosim::devices
