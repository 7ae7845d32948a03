#pragma once
/// \file
/// The networked HDC as an operator: the procedure loop takes its input
/// from whatever HDC is connected (holding the last input while none is,
/// so the scope stays where the hand left it), and the HDC gets back the
/// handle load of each step. Connections and disconnections are recorded
/// in the session, with the device's name (a connection is recorded when
/// its first frame, which carries the name, arrives). A link replaced by a
/// new one between two loop steps is still recorded as a disconnection and
/// a connection: the server counts its connections.
///
/// The device keeps the session's time: while an HDC is connected, next()
/// waits for the device's next frame and the loop steps on it as soon as it
/// arrives (one step per frame, so the loop answers a pose within its own
/// step time and never runs ahead of the person's hand); while none is, or
/// when the device falls silent for kFrameWait, the loop steps on the wall
/// clock, holding the last input. A loop slower than the device takes the
/// newest frame (frames in between are the device's, not the session's).
///
/// The host passes the operator to ProcedureLoop::step() as its
/// HandleLoadSink: the load then goes to the device as soon as the scope's
/// part of the step has it, before the colon's substeps and the recording.
/// A host that does not pass it is answered at the next call of next(),
/// after the whole step.

#include "simcore/devices/HdcServer.h"
#include "simcore/procedure/Operator.h"

#include <chrono>

namespace colonosim::devices {

class HdcOperator final : public procedure::Operator, public procedure::HandleLoadSink {
public:
    HdcOperator(int port, const HapticParameters& parameters, bool anyInterface = false)
        : m_server(port, parameters, anyInterface)
    {}

    /// Records connection changes in `loop`'s session (call before each step).
    void recordConnection(procedure::ProcedureLoop& loop);
    procedure::InputSample next(const procedure::ProcedureLoop& loop) override;
    /// Sends the step's load to the device, for the input it answers.
    void handleLoadReady(double handleForce, double handleTorque) override;
    [[nodiscard]] bool finished() const override { return false; }
    [[nodiscard]] bool keepsTime() const override { return true; }

    [[nodiscard]] const HdcServer& server() const { return m_server; }
    [[nodiscard]] long framesUsed() const { return m_frames; }

    /// s a connected loop waits for the device's next frame before it steps
    /// on the last input (two periods of a 1 kHz device).
    static constexpr double kFrameWait = 0.002;

private:
    using Clock = std::chrono::steady_clock;
    /// Waits until the wall clock is due for the next step, one loop step
    /// after the last (a fresh schedule after an overrun, no catch-up burst).
    void waitForWallClock(double loopStep);

    HdcServer m_server;
    Clock::time_point m_nextStep{};  ///< when the wall clock is due for a step without the device
    procedure::InputSample m_input;
    double m_inputTime = 0.0;
    bool m_connected = false;
    int m_connection = 0;      ///< the server's connection count when this one began
    bool m_announced = false;  ///< the connection is in the record (once its first frame named the device)
    long m_framesAtConnect = 0;
    bool m_sentOnce = false;
    bool m_answered = false;  ///< the last step's load went out early (handleLoadReady)
    long m_frames = 0;
    std::string m_device = "unknown";
};

}  // namespace colonosim::devices
