#pragma once
/// \file
/// The Haptic Device Controller: the process next to the device. Its servo
/// loop runs at the servo period whatever the simulator does: each tick it
/// reads the device, sends the input frame (OpenIGTLink) to the simulator,
/// takes whatever handle loads have arrived, and applies the servo's safe,
/// interpolated force. Without a simulator it keeps ticking (force zero) and
/// reconnects every reconnectInterval. The clock is steady_clock; tick()
/// can also be driven with explicit times (tests).

#include "simcore/devices/HapticDevice.h"
#include "simcore/devices/IgtlMessages.h"
#include "simcore/devices/TcpLink.h"
#include "simcore/devices/TimeHistogram.h"

#include <atomic>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

namespace colonosim::devices {

struct ServoStatistics {
    TimeHistogram periods;    ///< s between consecutive ticks
    TimeHistogram jitter;     ///< s, |period - servo period|
    TimeHistogram latencies;  ///< s from an input frame to the load computed from it
    int ticks = 0;
    int loadsReceived = 0;
    int messagesRefused = 0;
    int reconnects = 0;
    double maxOutputStep =
        0.0;  ///< N, largest change of the applied force in one tick, the stop's drop aside
    /// N: the force applied when an emergency stop latched, and the force
    /// that tick applied (zero: no ramp).
    double stopFromForce = 0.0;
    double stopToForce = 0.0;
};

class HdcController {
public:
    HdcController(HapticDevice& device, const HapticParameters& parameters, std::string host, int port);

    /// Runs the servo loop in real time until `stop` or `duration` s.
    void run(std::stop_token stop, double duration);
    /// One servo tick at local time `now` (s).
    void tick(double now);
    /// One tick on the servo's own clock instead of the wall clock: at
    /// (ticks so far) x servo period, for a host that ticks the servo itself
    /// once per loop step (lockstep: the run takes the computation's time).
    void tickLockstep() { tick(m_stats.ticks * m_servo.parameters().servoPeriod); }

    [[nodiscard]] const ForceServo& servo() const { return m_servo; }
    ForceServo& servo() { return m_servo; }
    [[nodiscard]] const ServoStatistics& statistics() const { return m_stats; }
    [[nodiscard]] bool connected() const { return m_link.open(); }
    /// From any thread: whether the link is up now, and whether it ever was.
    [[nodiscard]] bool linkUp() const { return m_linkUp.load(); }
    [[nodiscard]] bool everConnected() const { return m_everConnected.load(); }
    [[nodiscard]] const std::string& lastRefusal() const { return m_lastRefusal; }
    /// Drops the link (as a cable pulled would).
    void disconnect();
    /// From any thread: the next tick latches an emergency stop.
    void requestEmergencyStop() { m_emergencyRequest = true; }

private:
    void connectIfDue(double now);

    HapticDevice& m_device;
    ForceServo m_servo;
    std::string m_host;
    int m_port;
    TcpLink m_link;
    MessageReader m_reader;
    Bytes m_incoming;
    double m_nextConnect = 0.0;
    double m_lastTick = -1.0;
    bool m_stopReported = false;
    std::atomic<bool> m_emergencyRequest{false};
    std::atomic<bool> m_linkUp{false};
    std::atomic<bool> m_everConnected{false};
    std::string m_lastRefusal;
    ServoStatistics m_stats;
};

}  // namespace colonosim::devices
