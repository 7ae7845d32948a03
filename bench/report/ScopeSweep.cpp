#include "bench/report/ScopeSweep.h"

#include "bench/report/SceneRun.h"
#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/ReferenceSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace colonosim::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

scope::ScopeParameters withCounts(int nodes, int iterations)
{
    scope::ScopeParameters parameters;
    parameters.numNodes = nodes;
    parameters.solverIterations = iterations;
    return parameters;
}

/// The supported scope of `nodes` nodes, loaded, in its unloaded shape.
scope::Colonoscope coldScope(int nodes, int iterations)
{
    scope::Colonoscope result = realisticScope(withCounts(nodes, iterations));
    applyContactLoads(result, ScopeLoad::Supported);
    return result;
}

/// The reference equilibrium of the supported scope; warns when it did not converge.
scope::DiscreteRod referenceRod(int nodes, std::ostream& log)
{
    scope::DiscreteRod rod = coldScope(nodes, 1).rod();
    const scope::ReferenceResult result = scope::solveReference(rod);
    if (!result.converged) {
        log << "scope sweep: warning: the reference at " << nodes << " nodes did not converge (gradient "
            << result.gradientNorm << " N m)\n";
    }
    return rod;
}

/// The chain's converged fixed point, or nothing when the iteration does not settle.
bool chainFixedPoint(scope::DiscreteRod& rod)
{
    constexpr int kChunk = 100;
    constexpr int kMaxIterations = 200000;
    for (int done = 0; done < kMaxIterations; done += kChunk) {
        if (scope::solveChain(rod, kChunk, scope::ScopeParameters{}.solverRelaxation) < 1e-14) {
            return true;
        }
    }
    return false;
}

double largestNodeDistance(const scope::DiscreteRod& a, const scope::DiscreteRod& b)
{
    double largest = 0.0;
    for (size_t i = 0; i < a.position.size(); ++i) {
        largest = std::max(largest, (a.position[i] - b.position[i]).norm());
    }
    return largest;
}

}  // namespace

double measureScopeStepSeconds(const scope::ScopeParameters& parameters, ScopeLoad load,
                               const TimingScale& timing)
{
    scope::Colonoscope scope = realisticScope(parameters);
    const auto stepOnce = [&] {
        applyContactLoads(scope, load);
        scope.step();
    };
    // Warm-up, then the steps per block from a first estimate.
    long calibration = 0;
    const double start = processCpuSeconds();
    while (calibration < 3 || processCpuSeconds() - start < 0.1 * timing.blockSeconds) {
        stepOnce();
        ++calibration;
    }
    const double estimate = (processCpuSeconds() - start) / static_cast<double>(calibration);
    const long perBlock = std::max(1L, static_cast<long>(std::ceil(timing.blockSeconds / estimate)));
    std::vector<double> perStep;
    perStep.reserve(static_cast<size_t>(timing.samples));
    for (int s = 0; s < timing.samples; ++s) {
        const double blockStart = processCpuSeconds();
        for (long i = 0; i < perBlock; ++i) {
            stepOnce();
        }
        perStep.push_back((processCpuSeconds() - blockStart) / static_cast<double>(perBlock));
    }
    std::nth_element(perStep.begin(), perStep.begin() + timing.samples / 2, perStep.end());
    return perStep[static_cast<size_t>(timing.samples / 2)];
}

std::vector<ScopeSweepRow> runScopeSweep(const ScopeSweepOptions& options, std::ostream& log)
{
    const scope::DiscreteRod finest = referenceRod(options.finestNodes, log);
    std::vector<ScopeSweepRow> rows;
    for (const int nodes : options.nodeCounts) {
        const scope::DiscreteRod reference = referenceRod(nodes, log);
        scope::DiscreteRod fixedPoint = coldScope(nodes, 1).rod();
        const bool settled = chainFixedPoint(fixedPoint);
        const double discretisation = (reference.position.back() - finest.position.back()).norm();
        const double floor = settled ? (fixedPoint.position.back() - reference.position.back()).norm() : kNaN;
        for (const int iterations : options.iterationCounts) {
            scope::Colonoscope cold = coldScope(nodes, iterations);
            cold.step();
            const scope::DiscreteRod& rod = cold.rod();
            ScopeSweepRow row;
            row.nodes = nodes;
            row.insertedNodes = rod.numNodes();
            row.iterations = iterations;
            row.stepSeconds =
                measureScopeStepSeconds(withCounts(nodes, iterations), ScopeLoad::Supported, options.timing);
            row.tipError = (rod.position.back() - reference.position.back()).norm();
            row.maxNodeError = largestNodeDistance(rod, reference);
            row.iterationTipError =
                settled ? (rod.position.back() - fixedPoint.position.back()).norm() : kNaN;
            row.fixedPointTipError = floor;
            row.discretisationTipError = discretisation;
            row.totalTipError = (rod.position.back() - finest.position.back()).norm();
            log << "scope sweep: " << nodes << " nodes (" << row.insertedNodes << " inside), " << iterations
                << " iterations: " << row.stepSeconds * 1e6 << " us/step; tip error " << row.tipError
                << " m (max node " << row.maxNodeError << " m), iteration error " << row.iterationTipError
                << " m, discretisation " << row.discretisationTipError << " m, total " << row.totalTipError
                << " m\n";
            rows.push_back(row);
        }
    }
    return rows;
}

void writeScopeSweepCsv(const std::vector<ScopeSweepRow>& rows, std::ostream& out)
{
    const auto value = [&out](double v) -> std::ostream& {
        return std::isfinite(v) ? out << v : out << "NaN";
    };
    out << "nodes,inserted_nodes,iterations,step_us,tip_error_m,max_node_error_m,tip_iteration_error_m,"
           "fixed_point_tip_error_m,discretisation_tip_error_m,total_tip_error_m\n";
    out.precision(6);
    for (const ScopeSweepRow& row : rows) {
        out << row.nodes << ',' << row.insertedNodes << ',' << row.iterations << ',' << row.stepSeconds * 1e6
            << ',' << row.tipError << ',' << row.maxNodeError << ',';
        value(row.iterationTipError) << ',';
        value(row.fixedPointTipError)
            << ',' << row.discretisationTipError << ',' << row.totalTipError << '\n';
    }
}

}  // namespace colonosim::bench
