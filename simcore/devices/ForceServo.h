#pragma once
/// \file
/// The HDC's force path, run once per servo tick whatever the simulator's
/// cycle. Simulator updates (handle force and torque, with the simulator's
/// time) arrive at their own rate; between them the force is extrapolated
/// linearly from the last two updates for at most extrapolationHorizon, then
/// held. Safety, in this order, on every tick:
///   - non-finite commands are refused when they arrive (the last good one stays);
///   - an emergency stop latches the output at zero at once (no ramp);
///   - the link closed, or silent for longer than watchdogTimeout: the target is zero;
///   - the target is clamped to +-maxForce / +-maxTorque;
///   - the output moves towards the target by at most rateLimit * servoPeriod.
/// So a lost link reaches zero from full scale in maxForce / forceRateLimit
/// (5 ms by default), and no output step exceeds the rate limit.

#include "simcore/devices/HapticParameters.h"

namespace colonosim::devices {

struct HandleCommand {
    double force = 0.0;   ///< N along the insertion direction (+ resists insertion)
    double torque = 0.0;  ///< N m about the shaft
};

enum class ServoState { WaitingForSimulator, Following, Watchdog, LinkLost, EmergencyStop };

[[nodiscard]] const char* toString(ServoState state);

class ForceServo {
public:
    explicit ForceServo(const HapticParameters& parameters);

    /// A command from the simulator, stamped with the simulator's time (s).
    /// Returns false (and keeps the last good command) when it is not finite.
    bool receive(const HandleCommand& command, double simulatorTime, double localTime);
    /// The link to the simulator closed (or was found broken).
    void linkLost();
    /// A new link was made: the next command is followed again.
    void linkRestored();
    /// Latches the output at zero until reset().
    void emergencyStop();
    void reset();

    /// One servo tick at local time `now` (s): the force to apply.
    const HandleCommand& tick(double now);

    [[nodiscard]] ServoState state() const { return m_state; }
    [[nodiscard]] const HandleCommand& output() const { return m_output; }
    [[nodiscard]] int rejectedCommands() const { return m_rejected; }
    [[nodiscard]] const HapticParameters& parameters() const { return m_parameters; }

private:
    [[nodiscard]] HandleCommand target(double now) const;

    HapticParameters m_parameters;
    ServoState m_state = ServoState::WaitingForSimulator;
    HandleCommand m_last, m_before;
    double m_lastSimTime = 0.0, m_beforeSimTime = 0.0;
    double m_lastLocalTime = 0.0;
    int m_commands = 0;
    int m_rejected = 0;
    HandleCommand m_output;
};

}  // namespace colonosim::devices
