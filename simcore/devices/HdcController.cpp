#include "simcore/devices/HdcController.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace colonosim::devices {

namespace {
constexpr double kReconnectInterval = 0.2;  ///< s between connection attempts
}

HdcController::HdcController(HapticDevice& device, const HapticParameters& parameters, std::string host,
                             int port)
    : m_device(device), m_servo(parameters), m_host(std::move(host)), m_port(port),
      m_reader(static_cast<std::size_t>(parameters.maxMessageBytes))
{}

void HdcController::disconnect()
{
    m_link.close();
    m_servo.linkLost();
}

void HdcController::connectIfDue(double now)
{
    if (m_link.open() || now < m_nextConnect) {
        return;
    }
    m_nextConnect = now + kReconnectInterval;
    try {
        m_link = TcpLink::connect(m_host, m_port, 0.0005);
        m_reader = MessageReader(static_cast<std::size_t>(m_servo.parameters().maxMessageBytes));
        m_incoming.clear();
        m_servo.linkRestored();
        m_stopReported = false;
        ++m_stats.reconnects;
        // Say which device this is (the simulator records it with the session).
        m_link.send(encodeStatus(kDeviceStatusName, kStatusOk, m_device.name()), 0.001);
    } catch (const std::runtime_error&) {
        // Not there yet: keep ticking with zero force; try again later.
    }
}

void HdcController::tick(double now)
{
    if (m_lastTick >= 0.0) {
        m_stats.periods.add(now - m_lastTick);
        m_stats.jitter.add(std::abs(now - m_lastTick - m_servo.parameters().servoPeriod));
    }
    m_lastTick = now;
    ++m_stats.ticks;
    const bool stopRequested = m_device.emergencyStopPressed() || m_emergencyRequest.load();
    const bool stopLatches = stopRequested && m_servo.state() != ServoState::EmergencyStop;
    if (stopLatches) {
        m_stats.stopFromForce = m_servo.output().force;
    }
    if (stopRequested) {
        m_servo.emergencyStop();
    }
    connectIfDue(now);
    if (m_link.open()) {
        if (!m_link.send(encodeInput(m_device.read(), now), 0.0005)) {
            m_servo.linkLost();
        }
        if (m_servo.state() == ServoState::EmergencyStop && !m_stopReported) {
            m_link.send(encodeStatus(kDeviceStatusName, kStatusDisabled, "emergency stop"), 0.0005);
            m_stopReported = true;
        }
        m_incoming.clear();
        if (!m_link.receive(m_incoming, 0.0)) {
            m_servo.linkLost();
        }
        m_reader.feed(m_incoming.data(), m_incoming.size());
        std::string error;
        for (;;) {
            const std::optional<Message> m = m_reader.next(error);
            if (m) {
                if (m->kind == Message::Kind::HandleLoad) {
                    // The load carries the time of the input frame it was computed from.
                    if (m_servo.receive(HandleCommand{m->values[0], m->values[1]}, m->time, now)) {
                        ++m_stats.loadsReceived;
                        m_stats.latencies.add(now - m->time);
                    }
                } else if (m->kind == Message::Kind::Status && m->statusCode != kStatusOk) {
                    m_lastRefusal = m->statusText;
                }
                continue;
            }
            if (!error.empty()) {
                ++m_stats.messagesRefused;
                m_lastRefusal = error;
                if (m_reader.fatal()) {
                    disconnect();
                    break;
                }
                continue;
            }
            break;
        }
    }
    m_linkUp = m_link.open();
    m_everConnected = m_everConnected.load() || m_link.open();
    const double before = m_servo.output().force;
    const HandleCommand& out = m_servo.tick(now);
    m_stats.maxOutputStep = std::max(m_stats.maxOutputStep, std::abs(out.force - before));
    m_device.apply(out, m_servo.parameters().servoPeriod);
    if (stopLatches) {
        m_stats.stopToForce = out.force;
    }
}

void HdcController::run(std::stop_token stop, double duration)
{
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto period = std::chrono::duration<double>(m_servo.parameters().servoPeriod);
    auto next = start;
    while (!stop.stop_requested()) {
        const double now = std::chrono::duration<double>(Clock::now() - start).count();
        if (now >= duration) {
            break;
        }
        tick(now);
        next += std::chrono::duration_cast<Clock::duration>(period);
        const auto late = Clock::now();
        if (late > next) {
            next = late;  // overran: start a fresh schedule rather than catch up with back-to-back ticks
        }
        std::this_thread::sleep_until(next);
    }
    m_link.close();
}

}  // namespace colonosim::devices
