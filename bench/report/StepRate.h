#pragma once
/// \file
/// In-process timings for summary.json: the rate of single colon steps
/// (one integrator step of the whole loaded colon at the integrator's stable
/// step, backward Euler at 1 ms), and the cost of mapping the visual mesh
/// onto the physics mesh. Times are CPU time of this process, one thread.

#include "bench/report/BenchScene.h"
#include "simcore/physics/Integrator.h"

namespace colonosim::bench {

/// The step the report uses as "the stable step" of an integrator: the
/// bound of maxStableStep() on the scene's body at rest, or 1 ms for
/// backward Euler, s.
[[nodiscard]] double benchStableStep(const BenchScene& scene, physics::IntegratorKind kind);

/// Steps per second of one integrator step on the loaded colon, timed over
/// at least `minSeconds` of stepping after a warm-up of a few steps.
[[nodiscard]] double measureColonStepHz(const BenchScene& scene, physics::IntegratorKind kind,
                                        double minSeconds);

/// Median time of MeshMapping::apply (visual mesh onto the physics mesh,
/// deformed by the bench scene after a few loaded steps) over `repeats`, s.
[[nodiscard]] double measureMappingSeconds(const BenchScene& scene, int repeats);

}  // namespace colonosim::bench
