#pragma once
/// \file
/// Paces the procedure loop's fixed 1 ms steps to the wall clock, times the
/// replay's speed: simulated time follows anchor + speed * (wall - anchor).
/// The step's dt never comes from the clock (the loop's determinism); only
/// when a step runs does. A loop that falls behind runs its steps back to
/// back; once it is more than kMaxLag of simulated time behind, the debt is
/// dropped (the anchor moves up to it), so that when the steps get cheap
/// again (the colon asleep on the way out) the session does not run faster
/// than real time to make up what it lost, with the scope outrunning the
/// hands that drive it. Lags shorter than kMaxLag (a thread scheduled late)
/// are made up, so that a loop that keeps up holds real time on average.
/// Used by the trainer's loop thread (app/SimulationRunner.h) and by
/// `colonosim run` driven by a gamepad. Pure logic on the times it is given,
/// so that it is tested without a thread or a clock.

namespace colonosim::cli {

class LoopPacer {
public:
    /// s of simulated time a loop may fall behind before the debt is dropped.
    static constexpr double kMaxLag = 0.1;

    /// Starts pacing from simulated time `simTime` at wall time `wallTime`
    /// (s, any steady origin) at `speed` simulated seconds per wall second.
    /// Called again after a pause or a change of speed.
    void restart(double simTime, double wallTime, double speed);

    /// Wall time (s) at which the step from `simTime` to `simTime + dt` is
    /// due; at or before `wallTime` the step runs now. A loop found more than
    /// kMaxLag behind has the debt beyond kMaxLag dropped first.
    double dueAt(double simTime, double dt, double wallTime);

    /// Simulated seconds of lag dropped since the last restart().
    [[nodiscard]] double dropped() const { return m_dropped; }

private:
    double m_anchorSim = 0.0;
    double m_anchorWall = 0.0;
    double m_speed = 1.0;
    double m_dropped = 0.0;
};

}  // namespace colonosim::cli
