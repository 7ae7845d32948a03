#pragma once
/// \file
/// The colonoscope chain solver's speed against its error (ChainSolver.h),
/// with the Newton reference (ReferenceSolver.h) of the same discrete rod as
/// truth, over node and iteration counts, on the supported benchmark scope
/// (ScopeScene.h; the free load has no unique equilibrium to measure against).
///
/// Error: one scope step (`iterations` chain iterations) from cold, the
/// unloaded shape (straight joints, dials set) with the whole load applied at
/// once. This is the hardest step a session can ask for (a warm-started step
/// only absorbs the load change since the previous one), and the figure
/// depends on the iteration count alone, not on a chosen load history; with
/// a steady load, s warm steps of i iterations are one cold step of s i.
/// Besides the distance to the reference (tip and largest node distance), each
/// row gives the distance to the chain's own converged fixed point (the
/// iteration error, which the iterations remove), the fixed point's distance
/// to the reference (the floor: in 3-D the chain's fixed point differs from
/// the energy minimum, see ChainSolver.h), the reference's distance to the
/// finest reference (400 nodes; discretisation error, tip only: the tip is
/// the one material point every node count shares), and the step's tip
/// distance to the finest reference (total error).
///
/// The discretisation error is dominated by the dial-steered bending
/// section, whose length is rounded to whole elements (round(0.10 m / l)
/// joints: 0.108 m at 80 nodes, 0.098 m at 400), not by the rod's elasticity
/// (with the dials straight the 80-node tip is 1.2 mm from the 400-node tip).
///
/// Speed: median CPU time of one warm-started step (loads applied, then the
/// chain iterations), as in BM_ScopeStep but under the supported load. The
/// iteration count is fixed, yet the cost depends a little on the state: at 80
/// nodes a step of the free load (scope_step_us) takes about 15% longer.

#include "bench/report/ScopeScene.h"

#include <iosfwd>
#include <vector>

namespace colonosim::bench {

/// How long to time: `samples` blocks of at least `blockSeconds` each.
struct TimingScale {
    double blockSeconds = 0.01;  ///< CPU s per block
    int samples = 21;
};

struct ScopeSweepOptions {
    std::vector<int> nodeCounts{20, 40, 80, 100};
    std::vector<int> iterationCounts{5, 10, 20, 50, 100};
    int finestNodes = 400;  ///< the discretisation reference
    TimingScale timing;
};

struct ScopeSweepRow {
    int nodes = 0;                        ///< nodes over the working length
    int insertedNodes = 0;                ///< nodes inside at 1.2 m
    int iterations = 0;                   ///< chain iterations per step
    double stepSeconds = 0.0;             ///< median CPU time per step, s
    double tipError = 0.0;                ///< tip distance to the reference, m
    double maxNodeError = 0.0;            ///< largest node distance to the reference, m
    double iterationTipError = 0.0;       ///< tip distance to the chain's fixed point, m (NaN: none)
    double fixedPointTipError = 0.0;      ///< chain fixed point's tip to the reference, m (NaN: none)
    double discretisationTipError = 0.0;  ///< reference tip to the finest reference tip, m
    double totalTipError = 0.0;           ///< tip distance to the finest reference, m
};

/// Median CPU time of one step of a scope with `parameters` under `load`
/// (applyContactLoads then Colonoscope::step, warm-started), s.
[[nodiscard]] double measureScopeStepSeconds(const scope::ScopeParameters& parameters, ScopeLoad load,
                                             const TimingScale& timing);

/// Runs the sweep, one row per node count and iteration count; logs one line per row.
[[nodiscard]] std::vector<ScopeSweepRow> runScopeSweep(const ScopeSweepOptions& options, std::ostream& log);

/// Writes the rows as CSV (header nodes,inserted_nodes,iterations,step_us,
/// tip_error_m,max_node_error_m,tip_iteration_error_m,fixed_point_tip_error_m,
/// discretisation_tip_error_m,total_tip_error_m; NaN where there is no fixed point).
void writeScopeSweepCsv(const std::vector<ScopeSweepRow>& rows, std::ostream& out);

}  // namespace colonosim::bench
