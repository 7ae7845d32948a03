#include "trainer_ui/app/RenderScaleGovernor.h"

namespace colonosim::app {

void RenderScaleGovernor::restartWindow(double start, double drawTime)
{
    m_windowStart = start;
    m_frames = 1;
    m_drawSum = drawTime;
}

double RenderScaleGovernor::frameDrawn(double start, double drawTime)
{
    const bool resumed = m_lastStart >= 0.0 && start - m_lastStart > kGap;
    m_lastStart = start;
    if (m_windowStart < 0.0 || resumed || start < m_settleUntil) {
        restartWindow(start, drawTime);
        return scale();
    }
    ++m_frames;
    m_drawSum += drawTime;
    const double span = start - m_windowStart;
    if (span < kWindow || m_frames < 3) {
        return scale();
    }
    const double interval = span / static_cast<double>(m_frames - 1);
    const double draw = m_drawSum / static_cast<double>(m_frames);
    const double target = 1.0 / kTargetRate;
    std::size_t level = m_level;
    if (interval > 1.05 * target && draw >= kDrawShare * interval && m_level + 1 < kScales.size()) {
        ++level;
    } else if (m_level > 0) {
        // The next larger picture, its whole draw counted as pixels (the
        // draw's fixed part does not grow): it is taken only when even that
        // estimate keeps the rate.
        const double grow = kScales[m_level - 1] / kScales[m_level];
        if (interval + draw * (grow * grow - 1.0) < 0.95 * target) {
            --level;
        }
    }
    if (level != m_level) {
        m_level = level;
        ++m_changes;
        m_settleUntil = start + kSettle;
    }
    restartWindow(start, drawTime);
    return scale();
}

}  // namespace colonosim::app
