#pragma once
/// \file
/// What the active region (ActiveRegion.h) buys and costs: the bench scene
/// advanced by TissueSimulation (symplectic Euler, 1 ms loop steps with the
/// planned substeps, up to 64) with and without the active region at its default
/// SleepParameters, same load, same duration, both starting at rest in the
/// unloaded static equilibrium (gravity, insufflation) so the load is the
/// only disturbance. Speed-up = CPU time without /
/// CPU time with; error = node distances between the two end states (rms and
/// max, m); awake fraction = mean over loop steps of awake nodes / nodes.

#include "bench/report/BenchScene.h"

#include <iosfwd>

namespace colonosim::bench {

struct ActiveRegionResult {
    double speedup = 0.0;
    double rmsError = 0.0;       ///< m
    double maxError = 0.0;       ///< m
    double awakeFraction = 0.0;  ///< mean over loop steps
    double finalAwakeFraction = 0.0;
    double cpuFull = 0.0;    ///< s
    double cpuActive = 0.0;  ///< s
    double duration = 0.0;   ///< simulated, s
};

[[nodiscard]] ActiveRegionResult runActiveRegionStudy(const BenchScene& scene, double duration,
                                                      std::ostream& log);

}  // namespace colonosim::bench
