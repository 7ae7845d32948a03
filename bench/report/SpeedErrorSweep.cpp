#include "bench/report/SpeedErrorSweep.h"

#include "bench/report/StepRate.h"

#include <cmath>
#include <iomanip>
#include <ostream>

namespace colonosim::bench {

using physics::IntegratorKind;

ReferenceSolution computeReference(const BenchScene& scene, double duration, std::ostream& log)
{
    const double hs = benchStableStep(scene, IntegratorKind::RungeKutta4);
    ReferenceSolution reference;
    const RunResult fine = runScene(scene, IntegratorKind::RungeKutta4, hs / 16.0, duration);
    reference.step = fine.step;
    reference.halfResolution = runScene(scene, IntegratorKind::RungeKutta4, hs / 8.0, duration);
    if (!fine.stable || !reference.halfResolution.stable) {
        log << "reference: RK4 at h_s/16 or h_s/8 went unstable\n";
        reference.selfError = reference.selfErrorMax = NAN;
        return reference;
    }
    reference.positions = fine.finalPositions;
    const PositionError self = positionError(reference.halfResolution.finalPositions, fine.finalPositions);
    reference.selfError = self.rms;
    reference.selfErrorMax = self.max;
    log << "reference: rk4 at " << reference.step * 1e6 << " us, " << fine.cpuSeconds
        << " s CPU; self-consistency "
        << "(rk4 h_s/8 vs h_s/16): rms " << self.rms << " m, max " << self.max << " m\n";
    return reference;
}

namespace {
std::vector<double> stepsFor(const BenchScene& scene, IntegratorKind kind)
{
    if (kind == IntegratorKind::BackwardEuler) {
        return {1e-3, 0.5e-3, 0.25e-3, 0.125e-3, 4e-3};
    }
    const double hs = benchStableStep(scene, kind);
    return {hs, hs / 2.0, hs / 4.0, hs / 8.0, 1.5 * hs};
}
}  // namespace

std::vector<SweepRow> runSpeedErrorSweep(const BenchScene& scene, double duration,
                                         const ReferenceSolution& reference, std::ostream& log)
{
    std::vector<SweepRow> rows;
    const double rk4Eighth = benchStableStep(scene, IntegratorKind::RungeKutta4) / 8.0;
    for (const IntegratorKind kind : physics::kAllIntegrators) {
        for (const double h : stepsFor(scene, kind)) {
            const bool reuse = kind == IntegratorKind::RungeKutta4 && h == rk4Eighth;
            const RunResult run = reuse ? reference.halfResolution : runScene(scene, kind, h, duration);
            SweepRow row{std::string(physics::integratorName(kind)),
                         run.step,
                         run.stable,
                         run.cpuPerSimulatedSecond(),
                         NAN,
                         NAN};
            if (run.stable) {
                const PositionError error = positionError(run.finalPositions, reference.positions);
                row.rmsError = error.rms;
                row.maxError = error.max;
            }
            log << std::setw(17) << row.integrator << "  h " << std::setw(10) << run.step * 1e6 << " us  "
                << (row.stable ? "stable  " : "UNSTABLE") << "  cpu/sim " << std::setw(9)
                << row.cpuPerSimulatedSecond << "  rms " << row.rmsError << " m  max " << row.maxError
                << " m\n";
            rows.push_back(row);
        }
    }
    return rows;
}

void writeSweepCsv(const std::vector<SweepRow>& rows, std::ostream& out)
{
    out << "integrator,step_s,stable,cpu_s_per_simulated_s,rms_error_m,max_error_m\n";
    out << std::setprecision(9);
    for (const SweepRow& row : rows) {
        out << row.integrator << ',' << row.step << ',' << (row.stable ? 1 : 0) << ','
            << row.cpuPerSimulatedSecond << ',';
        if (row.stable) {
            out << row.rmsError << ',' << row.maxError << '\n';
        } else {
            out << "NaN,NaN\n";
        }
    }
}

}  // namespace colonosim::bench
