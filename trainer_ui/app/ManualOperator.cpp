#include "trainer_ui/app/ManualOperator.h"

namespace colonosim::app {

procedure::InputSample ManualOperator::next(const procedure::ProcedureLoop& loop)
{
    m_controls.fetch();
    devices::ManualControls controls = m_controls.front();
    controls.buttons |= m_pressed.exchange(0, std::memory_order_acq_rel);
    return m_input.update(controls, loop.trace().loopStep);
}

}  // namespace colonosim::app
