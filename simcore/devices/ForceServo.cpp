#include "simcore/devices/ForceServo.h"

#include <algorithm>
#include <cmath>

namespace colonosim::devices {

const char* toString(ServoState state)
{
    switch (state) {
    case ServoState::WaitingForSimulator: return "waiting for simulator";
    case ServoState::Following: return "following";
    case ServoState::Watchdog: return "watchdog: simulator silent";
    case ServoState::LinkLost: return "link lost";
    case ServoState::EmergencyStop: return "emergency stop";
    }
    return "unknown";
}

ForceServo::ForceServo(const HapticParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
}

bool ForceServo::receive(const HandleCommand& command, double simulatorTime, double localTime)
{
    if (!std::isfinite(command.force) || !std::isfinite(command.torque) || !std::isfinite(simulatorTime)) {
        ++m_rejected;
        return false;
    }
    // A trend needs two consecutive commands of one unbroken stream.
    const bool streaming = m_state == ServoState::Following;
    if (streaming && m_commands > 0 && simulatorTime > m_lastSimTime) {
        m_before = m_last;
        m_beforeSimTime = m_lastSimTime;
    } else {
        m_before = command;
        m_beforeSimTime = simulatorTime;
    }
    m_last = command;
    m_lastSimTime = simulatorTime;
    m_lastLocalTime = localTime;
    ++m_commands;
    if (m_state == ServoState::WaitingForSimulator || m_state == ServoState::Watchdog) {
        m_state = ServoState::Following;
    }
    return true;
}

void ForceServo::linkLost()
{
    if (m_state != ServoState::EmergencyStop) {
        m_state = ServoState::LinkLost;
    }
}

void ForceServo::linkRestored()
{
    if (m_state == ServoState::LinkLost) {
        m_state = ServoState::WaitingForSimulator;
        m_commands = 0;
    }
}

void ForceServo::emergencyStop()
{
    m_state = ServoState::EmergencyStop;
    m_output = HandleCommand{};
}

void ForceServo::reset()
{
    m_state = ServoState::WaitingForSimulator;
    m_commands = 0;
    m_output = HandleCommand{};
}

HandleCommand ForceServo::target(double now) const
{
    if (m_state != ServoState::Following || m_commands == 0) {
        return HandleCommand{};
    }
    // Linear extrapolation in the simulator's time, which advances with the
    // local clock; limited to the horizon, then held.
    const double span = m_lastSimTime - m_beforeSimTime;
    const double ahead = std::clamp(now - m_lastLocalTime, 0.0, m_parameters.extrapolationHorizon);
    HandleCommand t = m_last;
    if (span > 0.0) {
        t.force += (m_last.force - m_before.force) / span * ahead;
        t.torque += (m_last.torque - m_before.torque) / span * ahead;
    }
    return t;
}

const HandleCommand& ForceServo::tick(double now)
{
    if (m_state == ServoState::EmergencyStop) {
        m_output = HandleCommand{};
        return m_output;
    }
    if (m_state == ServoState::Following && now - m_lastLocalTime > m_parameters.watchdogTimeout) {
        m_state = ServoState::Watchdog;
    }
    HandleCommand goal = target(now);
    goal.force = std::clamp(goal.force, -m_parameters.maxForce, m_parameters.maxForce);
    goal.torque = std::clamp(goal.torque, -m_parameters.maxTorque, m_parameters.maxTorque);
    const double df = m_parameters.forceRateLimit * m_parameters.servoPeriod;
    const double dt = m_parameters.torqueRateLimit * m_parameters.servoPeriod;
    // Towards the goal by at most the rate limit; onto it exactly when within reach.
    const auto approach = [](double from, double to, double step) {
        return std::abs(to - from) <= step * (1.0 + 1e-9) ? to : from + std::copysign(step, to - from);
    };
    m_output.force = approach(m_output.force, goal.force, df);
    m_output.torque = approach(m_output.torque, goal.torque, dt);
    return m_output;
}

}  // namespace colonosim::devices
