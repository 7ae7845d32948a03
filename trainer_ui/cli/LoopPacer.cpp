#include "trainer_ui/cli/LoopPacer.h"

namespace colonosim::cli {

void LoopPacer::restart(double simTime, double wallTime, double speed)
{
    m_anchorSim = simTime;
    m_anchorWall = wallTime;
    m_speed = speed;
    m_dropped = 0.0;
}

double LoopPacer::dueAt(double simTime, double dt, double wallTime)
{
    // Where simulated time should be now, and how far the loop is behind it.
    const double due = m_anchorSim + m_speed * (wallTime - m_anchorWall);
    const double lag = due - simTime;
    if (lag > kMaxLag) {
        // Keep kMaxLag of the debt (made up as the loop can) and drop the rest.
        m_dropped += lag - kMaxLag;
        m_anchorSim = simTime + kMaxLag;
        m_anchorWall = wallTime;
    }
    return m_anchorWall + (simTime + dt - m_anchorSim) / m_speed;
}

}  // namespace colonosim::cli
