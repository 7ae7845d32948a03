#pragma once
/// \file
/// The loaded colonoscope of the scope benchmarks (bench_scope and the
/// report's scope sweep, ScopeSweep.h): the default scope inserted 1.2 m
/// along +x, dials at 0.6 rad up/down and -0.2 rad left/right, shaft turned
/// 0.3 rad. Its loads are re-applied every step, as the contact code does:
///
/// - side forces of 0.05-0.2 N, each with a 0.02 N push back along -x
///   (contact-like: a lumen pushing on the shaft), at the material points of
///   every fifth node of the default 80-node scope (counted from the base,
///   tip node excluded); a scope with another node count carries the same
///   forces, each split by the lever rule between the two nodes of the rigid
///   element it lies on (same resultant, same moment), so a sweep over node
///   counts solves one physical problem (at 80 nodes they sit on the nodes);
/// - a tip contact: (-0.3, 0.05, 0) N with ScopeLoad::Free, only its lateral
///   part (0, 0.05, 0) N with ScopeLoad::Supported;
/// - the scope's weight (gravity 9.81 m/s^2 along -z), with ScopeLoad::Free only.
///
/// Free is bench_scope's timing load. A free rod cannot carry it: the 0.3 N
/// axial tip push is about five times the Euler load of the 1.2 m cantilever
/// (pi^2 EI / (4 L^2) = 0.057 N) and its weight bends it with
/// q L^3 / EI of about 100, so it has several equilibria (the reference
/// solver lands on different ones depending on its load stepping) and the
/// chain solver does not settle on any. In the colon the wall carries both.
/// Supported drops them (the wall's share), keeping the contact forces:
/// one equilibrium, which the chain solver reaches; the accuracy sweep uses it.

#include "simcore/scope/Colonoscope.h"
#include "simcore/scope/ScopeParameters.h"

namespace colonosim::bench {

/// Inserted length of the benchmark scope, m.
inline constexpr double kBenchScopeInsertion = 1.2;

enum class ScopeLoad {
    Free,       ///< weight and the full tip contact (timing load)
    Supported,  ///< no weight, lateral tip contact only (accuracy load)
};

/// The benchmark scope (straight joints, dials set), not yet loaded.
[[nodiscard]] scope::Colonoscope realisticScope(const scope::ScopeParameters& parameters = {});

/// Clears the scope's loads and applies the benchmark loads (see above).
/// Allocation-free: it runs inside timed loops.
void applyContactLoads(scope::Colonoscope& scope, ScopeLoad load = ScopeLoad::Free);

}  // namespace colonosim::bench
