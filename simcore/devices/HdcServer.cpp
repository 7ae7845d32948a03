#include "simcore/devices/HdcServer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include <sys/eventfd.h>
#include <unistd.h>

namespace colonosim::devices {

HdcServer::HdcServer(int port, const HapticParameters& parameters, bool anyInterface)
    : m_parameters(parameters), m_listener(port, !anyInterface)
{
    m_parameters.validate();
    m_wake = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    m_thread = std::jthread([this](std::stop_token stop) { serve(stop); });
}

HdcServer::~HdcServer()
{
    m_thread.request_stop();
    if (m_thread.joinable()) {
        m_thread.join();
    }
    if (m_wake >= 0) {
        ::close(m_wake);
    }
}

std::optional<StampedInput> HdcServer::latestInput()
{
    // The count first: a frame counted after it is read with it or after.
    m_framesTaken = m_framesWritten.load(std::memory_order_acquire);
    StampedInput in;
    if (m_inputs.read(in)) {
        return in;
    }
    return std::nullopt;
}

std::optional<StampedInput> HdcServer::waitForInput(double timeout)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point now = Clock::now();
    const auto after = [now](double seconds) {
        return now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    };
    const Clock::time_point deadline = after(std::max(timeout, 0.0));
    const Clock::time_point pollUntil = std::min(deadline, after(kPollFor));
    const auto fresh = [this] { return m_framesWritten.load(std::memory_order_acquire) != m_framesTaken; };
    for (;;) {
        bool arrived = fresh();
        while (!arrived && Clock::now() < pollUntil) {
            std::this_thread::yield();  // the core stays busy, but any thread waiting for it runs
            arrived = fresh();
        }
        if (!arrived) {
            std::unique_lock lock(m_arrivalMutex);
            arrived = m_arrival.wait_until(lock, deadline, fresh);
        }
        // A frame counted after the last take may already have been read
        // with it: then there is nothing fresh, and the wait goes on.
        if (std::optional<StampedInput> in = latestInput(); in || !arrived) {
            return in;
        }
    }
}

void HdcServer::publishLoad(const HandleCommand& load, double inputTime)
{
    m_loads.write(StampedLoad{load, inputTime, ++m_loadSequence});
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(m_wake, &one, sizeof one);  // never blocks (EFD_NONBLOCK)
}

void HdcServer::serve(std::stop_token stop)
{
    const auto maxBody = static_cast<std::size_t>(m_parameters.maxMessageBytes);
    TcpLink link;
    MessageReader reader(maxBody);
    Bytes incoming;
    StampedInput frame;
    long lastSent = 0;
    while (!stop.stop_requested()) {
        if (!link.open()) {
            m_connected = false;
            link = m_listener.accept(0.002);
            if (link.open()) {
                reader = MessageReader(maxBody);
                std::snprintf(frame.device, sizeof frame.device, "%s", "unknown");
                ++m_connections;  // before the state: whoever sees it connected sees this count
                m_connected = true;
            }
            continue;
        }
        // One HDC at a time: anyone else is told why and closed.
        if (TcpLink other = m_listener.accept(0.0); other.open()) {
            ++m_refusedConnections;  // counted before the refusal is sent: whoever reads it sees the count
            other.send(encodeStatus(kSimulatorStatusName, kStatusBusy, "busy: another HDC is connected"),
                       0.01);
            other.close();
        }
        incoming.clear();
        // Sleeps until the HDC sends or the simulator publishes a load (or 2 ms pass).
        const bool alive = link.receive(incoming, 0.002, m_wake);
        std::uint64_t drained = 0;
        [[maybe_unused]] const ssize_t n = ::read(m_wake, &drained, sizeof drained);
        reader.feed(incoming.data(), incoming.size());
        std::string error;
        for (;;) {
            const std::optional<Message> m = reader.next(error);
            if (!m) {
                if (!error.empty()) {
                    ++m_refusedMessages;
                    if (reader.fatal()) {
                        link.close();
                        break;
                    }
                    continue;
                }
                break;
            }
            switch (m->kind) {
            case Message::Kind::Pose: frame.input.insertion = m->insertion; break;
            case Message::Kind::Angles:
                frame.input.rotation = m->values[0];
                frame.input.dialUpDown = m->values[1];
                frame.input.dialLeftRight = m->values[2];
                break;
            case Message::Kind::Buttons:  // the last message of a frame
                frame.input.buttons = m->buttons;
                frame.time = m->time;
                ++frame.frame;
                m_inputs.write(frame);
                {
                    const std::lock_guard lock(m_arrivalMutex);  // no wake-up lost between a check and a wait
                    m_framesWritten.fetch_add(1, std::memory_order_release);
                }
                m_arrival.notify_one();
                break;
            case Message::Kind::Status:
                m_emergencyStop = m->statusCode == kStatusDisabled;
                if (m->statusCode == kStatusOk && !m->statusText.empty()) {
                    std::snprintf(frame.device, sizeof frame.device, "%s", m->statusText.c_str());
                }
                break;
            case Message::Kind::HandleLoad:
                ++m_refusedMessages;  // not ours to receive
                break;
            }
        }
        StampedLoad load;
        if (m_loads.read(load) && load.sequence != lastSent && link.open()) {
            lastSent = load.sequence;
            link.send(encodeHandleLoad(load.load, load.inputTime), 0.001);
        }
        if (!alive) {
            link.close();
        }
    }
}

}  // namespace colonosim::devices
