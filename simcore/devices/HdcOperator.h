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

#include "simcore/devices/HdcServer.h"
#include "simcore/procedure/Operator.h"

namespace colonosim::devices {

class HdcOperator final : public procedure::Operator {
public:
    HdcOperator(int port, const HapticParameters& parameters, bool anyInterface = false)
        : m_server(port, parameters, anyInterface)
    {}

    /// Records connection changes in `loop`'s session (call before each step).
    void recordConnection(procedure::ProcedureLoop& loop);
    procedure::InputSample next(const procedure::ProcedureLoop& loop) override;
    [[nodiscard]] bool finished() const override { return false; }

    [[nodiscard]] const HdcServer& server() const { return m_server; }
    [[nodiscard]] long framesUsed() const { return m_frames; }

private:
    HdcServer m_server;
    procedure::InputSample m_input;
    double m_inputTime = 0.0;
    bool m_connected = false;
    int m_connection = 0;      ///< the server's connection count when this one began
    bool m_announced = false;  ///< the connection is in the record (once its first frame named the device)
    long m_framesAtConnect = 0;
    bool m_sentOnce = false;
    long m_frames = 0;
    std::string m_device = "unknown";
};

}  // namespace colonosim::devices
