#pragma once
/// \file
/// The speed-versus-error sweep: the bench scene run by every integrator at
/// a ladder of steps, each compared at the end with a converged reference.
///
/// Steps: explicit integrators at h_s (the stability bound of
/// StabilityBound.h), h_s/2, h_s/4, h_s/8 and 1.5 h_s (above the bound, to
/// show the instability); backward Euler at 1, 0.5, 0.25, 0.125 ms and 4 ms.
/// Reference: RK4 at h_s(RK4)/16. Its self-consistency is the distance
/// between RK4 at h_s/8 and at h_s/16 (for a fourth-order method the
/// reference's own error is about 1/15 of it).
/// Error: rms and largest node distance at the end, m. Cost: CPU seconds per
/// simulated second.

#include "bench/report/BenchScene.h"
#include "bench/report/SceneRun.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace colonosim::bench {

struct SweepRow {
    std::string integrator;
    double step = 0.0;  ///< s
    bool stable = true;
    double cpuPerSimulatedSecond = 0.0;
    double rmsError = 0.0;  ///< m (NaN when unstable)
    double maxError = 0.0;  ///< m (NaN when unstable)
};

struct ReferenceSolution {
    physics::Positions positions;  ///< at the end of the duration
    double step = 0.0;             ///< s
    double selfError = 0.0;        ///< rms distance RK4 h_s/8 vs h_s/16, m
    double selfErrorMax = 0.0;     ///< largest node distance of the same, m
    RunResult halfResolution;      ///< the h_s/8 run (reused by the sweep)
};

/// Runs the reference (and its h_s/8 companion) for `duration` seconds.
[[nodiscard]] ReferenceSolution computeReference(const BenchScene& scene, double duration, std::ostream& log);

/// Runs the sweep for every integrator; logs one line per row.
[[nodiscard]] std::vector<SweepRow> runSpeedErrorSweep(const BenchScene& scene, double duration,
                                                       const ReferenceSolution& reference, std::ostream& log);

/// Writes the rows as CSV (header integrator,step_s,stable,
/// cpu_s_per_simulated_s,rms_error_m,max_error_m; NaN for unstable errors).
void writeSweepCsv(const std::vector<SweepRow>& rows, std::ostream& out);

}  // namespace colonosim::bench
