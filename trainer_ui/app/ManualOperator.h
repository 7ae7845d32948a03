#pragma once
/// \file
/// The keyboard and mouse as an Operator: the UI thread hands in the held
/// controls (rates in [-1, 1]) through a triple buffer and momentary button
/// presses through an atomic latch, so a press shorter than one loop step is
/// still seen once; the loop thread integrates them with devices::ManualInput
/// at the loop step. Neither thread waits for the other.

#include "simcore/devices/ManualInput.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/app/TripleBuffer.h"

#include <atomic>
#include <cstdint>

namespace colonosim::app {

class ManualOperator final : public procedure::Operator {
public:
    explicit ManualOperator(const devices::ManualRates& rates = {}) : m_input(rates) {}

    /// UI thread: the controls held now.
    void setControls(const devices::ManualControls& controls)
    {
        m_controls.back() = controls;
        m_controls.publish();
    }
    /// UI thread: buttons pressed once (lens wash, mark lesion), seen by the next step.
    void press(std::uint8_t buttons) { m_pressed.fetch_or(buttons, std::memory_order_acq_rel); }

    /// Loop thread.
    procedure::InputSample next(const procedure::ProcedureLoop& loop) override;
    [[nodiscard]] bool finished() const override { return false; }

private:
    TripleBuffer<devices::ManualControls> m_controls;
    std::atomic<std::uint8_t> m_pressed{0};
    devices::ManualInput m_input;
};

}  // namespace colonosim::app
