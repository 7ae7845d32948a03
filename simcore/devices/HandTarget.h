#pragma once
/// \file
/// A scripted operator's hand as a simulated device's virtual hand sees it:
/// the operator (on the loop's thread) publishes where it wants the scope,
/// and the device (on the HDC's servo thread) follows the newest target. So
/// an operator can close its loop through the device, as a person does,
/// rather than through the loop's input.

#include "simcore/devices/TripleBuffer.h"
#include "simcore/procedure/DeviceInput.h"

namespace colonosim::devices {

class HandTarget {
public:
    /// Loop thread: the hand's new target.
    void publish(const procedure::InputSample& target) { m_buffer.write(target); }
    /// Servo thread only: the newest target published (the last one when none is new).
    procedure::InputSample latest()
    {
        m_buffer.read(m_last);
        return m_last;
    }

private:
    TripleBuffer<procedure::InputSample> m_buffer;
    procedure::InputSample m_last;
};

}  // namespace colonosim::devices
