#pragma once
/// \file
/// The simulator's side of the HDC link, on its own device I/O thread (a
/// std::jthread). It accepts one HDC at a time and refuses any other with a
/// STATUS "busy" message before closing it; it survives the HDC leaving and
/// coming back. Input frames reach the procedure loop through a triple
/// buffer (latestInput(), never waits; waitForInput(), which the loop uses
/// to step on each frame as it arrives); handle loads go back the same way
/// (publishLoad()). The procedure thread never touches a socket.
///
/// waitForInput() first polls for the frame, yielding its core to any
/// thread waiting for it, for up to kPollFor, and only then sleeps: a
/// procedure thread put to sleep between frames wakes on a core that has
/// gone idle, and the step it then runs takes longer (bench/paced_loop: the
/// push into the sigmoid paced at 1 kHz, a step's median 0.90-1.04 ms after
/// a sleep against 0.68-0.74 ms after polling). The poll is bounded because
/// the frame comes through the I/O thread: on a machine whose cores are all
/// busy, an unbounded poll kept that thread off the cores often enough that
/// 412 of 267,535 steps of the whole procedure through the HDC went without
/// their frame (HdcEndToEnd.*WholeProcedure*, while other tests ran on the
/// second core).

#include "simcore/devices/HapticParameters.h"
#include "simcore/devices/IgtlMessages.h"
#include "simcore/devices/TcpLink.h"
#include "simcore/devices/TripleBuffer.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace colonosim::devices {

struct StampedInput {
    procedure::InputSample input;
    double time = 0.0;            ///< the HDC's time of the frame, s
    long frame = 0;               ///< frames received so far
    char device[32] = "unknown";  ///< the device's name, from its STATUS on connecting
};

struct StampedLoad {
    HandleCommand load;
    double inputTime = 0.0;  ///< time of the input frame the load was computed from, s
    long sequence = 0;
};

class HdcServer {
public:
    /// Listens on `port` (0: any free port) on the loopback unless `anyInterface`.
    HdcServer(int port, const HapticParameters& parameters, bool anyInterface = false);
    ~HdcServer();
    HdcServer(const HdcServer&) = delete;
    HdcServer& operator=(const HdcServer&) = delete;

    [[nodiscard]] int port() const { return m_listener.port(); }
    /// The newest complete input frame since the last call, if any.
    std::optional<StampedInput> latestInput();
    /// The newest input frame since the last call of either, waiting up to
    /// `timeout` seconds for one to arrive; nothing when none came by then.
    std::optional<StampedInput> waitForInput(double timeout);
    /// s: how long waitForInput() polls before it sleeps (a servo period).
    static constexpr double kPollFor = 0.001;
    /// Sends the handle load computed from the input frame of time `inputTime`.
    void publishLoad(const HandleCommand& load, double inputTime);
    /// Loads published so far (read on the thread that publishes them).
    [[nodiscard]] long loadsPublished() const { return m_loadSequence; }

    [[nodiscard]] bool connected() const { return m_connected.load(); }
    [[nodiscard]] int connections() const { return m_connections.load(); }
    [[nodiscard]] int refusedConnections() const { return m_refusedConnections.load(); }
    [[nodiscard]] int refusedMessages() const { return m_refusedMessages.load(); }
    [[nodiscard]] bool emergencyStop() const { return m_emergencyStop.load(); }

private:
    void serve(std::stop_token stop);

    HapticParameters m_parameters;
    TcpListener m_listener;
    TripleBuffer<StampedInput> m_inputs;
    std::mutex m_arrivalMutex;
    std::condition_variable m_arrival;  ///< notified by the I/O thread after each frame it writes
    /// Raised under m_arrivalMutex after each frame; polled without it.
    std::atomic<long> m_framesWritten{0};
    long m_framesTaken = 0;  ///< procedure thread's: m_framesWritten when it last took a frame
    TripleBuffer<StampedLoad> m_loads;
    long m_loadSequence = 0;
    std::atomic<bool> m_connected{false};
    std::atomic<bool> m_emergencyStop{false};
    std::atomic<int> m_connections{0};
    std::atomic<int> m_refusedConnections{0};
    std::atomic<int> m_refusedMessages{0};
    int m_wake = -1;  ///< eventfd: publishLoad() wakes the I/O thread at once
    std::jthread m_thread;
};

}  // namespace colonosim::devices
