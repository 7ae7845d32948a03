#pragma once
/// \file
/// Runs the bench scene (BenchScene.h) from rest for a fixed simulated
/// duration with one integrator at one fixed step h, calling the integrator
/// directly (no substep planning), the standard load evaluated at the middle
/// of each step (exact impulse for the linear ramp). The run is declared unstable, and stopped, as soon as a
/// position or velocity is not finite or a node moves faster than
/// kUnstableSpeed; its cost is still reported per simulated second.

#include "bench/report/BenchScene.h"
#include "simcore/physics/Integrator.h"

namespace colonosim::bench {

/// Node speed above which a run counts as unstable (SteppingPolicy's default
/// maxNodeSpeed), m/s.
inline constexpr double kUnstableSpeed = 20.0;

struct RunResult {
    bool stable = true;
    double step = 0.0;                  ///< s, the step used
    long steps = 0;                     ///< steps taken
    double simulatedTime = 0.0;         ///< s
    double cpuSeconds = 0.0;            ///< CPU time of the stepping loop, s
    physics::Positions finalPositions;  ///< at the end (stable runs only)

    [[nodiscard]] double cpuPerSimulatedSecond() const
    {
        return simulatedTime > 0.0 ? cpuSeconds / simulatedTime : 0.0;
    }
};

/// Simulates exactly `duration` seconds in whole steps: the step used is
/// duration / ceil(duration / requestedStep), at most requestedStep, so
/// every run ends at the same time as the reference.
[[nodiscard]] RunResult runScene(const BenchScene& scene, physics::IntegratorKind kind, double requestedStep,
                                 double duration);

/// Root-mean-square and largest node distance between two position sets, m.
struct PositionError {
    double rms = 0.0;
    double max = 0.0;
};
[[nodiscard]] PositionError positionError(const physics::Positions& a, const physics::Positions& b);

/// CPU time of this process, s.
[[nodiscard]] double processCpuSeconds();

}  // namespace colonosim::bench
