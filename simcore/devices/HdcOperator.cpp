#include "simcore/devices/HdcOperator.h"

#include <thread>

namespace colonosim::devices {

void HdcOperator::waitForWallClock(double loopStep)
{
    const Clock::time_point now = Clock::now();
    if (m_nextStep < now) {
        m_nextStep = now;  // overran, or the first step: a fresh schedule
    } else {
        std::this_thread::sleep_until(m_nextStep);
    }
    m_nextStep += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(loopStep));
}

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

void HdcOperator::handleLoadReady(double handleForce, double handleTorque)
{
    m_server.publishLoad(HandleCommand{handleForce, handleTorque}, m_inputTime);
    m_answered = true;
}

procedure::InputSample HdcOperator::next(const procedure::ProcedureLoop& loop)
{
    if (!m_answered && (m_sentOnce || loop.time() > 0.0)) {
        // The load of the step just taken, for the input it was computed from.
        m_server.publishLoad(HandleCommand{loop.outputs().handleForce, loop.outputs().handleTorque},
                             m_inputTime);
    }
    m_answered = false;
    m_sentOnce = true;
    const double loopStep = loop.trace().loopStep;
    std::optional<StampedInput> in;
    if (m_server.connected()) {
        // Steps on the device's frame the moment it arrives; a silent device
        // (kFrameWait without a frame) leaves the last input held.
        in = m_server.waitForInput(kFrameWait);
        m_nextStep = Clock::now() +
                     std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(loopStep));
    } else {
        waitForWallClock(loopStep);
        in = m_server.latestInput();
    }
    if (in) {
        m_input = in->input;
        m_inputTime = in->time;
        m_device = in->device;
        ++m_frames;
    }
    return m_input;
}

}  // namespace colonosim::devices
