#include "simcore/devices/HdcOperator.h"

namespace colonosim::devices {

void HdcOperator::recordConnection(procedure::ProcedureLoop& loop)
{
    // The state first: the server counts a connection before it says it is
    // connected, so the count read after covers the link seen connected.
    const bool connected = m_server.connected();
    const int connection = m_server.connections();
    if (m_connected && connection != m_connection) {
        // The link we knew ended and another began since the last step.
        m_connected = false;
        if (m_announced) {
            loop.noteDevice(m_device, false);
        }
    }
    if (connected && !m_connected) {
        m_connected = true;
        m_connection = connection;
        m_announced = false;
        m_framesAtConnect = m_frames;
    }
    if (m_connected && !m_announced && m_frames > m_framesAtConnect) {
        loop.noteDevice(m_device, true);
        m_announced = true;
    }
    if (!connected && m_connected) {
        m_connected = false;
        if (m_announced) {
            loop.noteDevice(m_device, false);
        }
    }
}

procedure::InputSample HdcOperator::next(const procedure::ProcedureLoop& loop)
{
    if (m_sentOnce || loop.time() > 0.0) {
        // The load of the step just taken, for the input it was computed from.
        m_server.publishLoad(HandleCommand{loop.outputs().handleForce, loop.outputs().handleTorque},
                             m_inputTime);
    }
    m_sentOnce = true;
    if (std::optional<StampedInput> in = m_server.latestInput()) {
        m_input = in->input;
        m_inputTime = in->time;
        m_device = in->device;
        ++m_frames;
    }
    return m_input;
}

}  // namespace colonosim::devices
