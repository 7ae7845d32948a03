#pragma once
/// \file
/// The bench report: speed versus error of every integrator on the fixed
/// bench scene (BenchScene.h), the Bullet btSoftBody peer on the same terms
/// (BulletPeer.h), the active region's speed-up and error
/// (ActiveRegionStudy.h), the raw step and mapping rates (StepRate.h), the
/// colonoscope step at the paper's setting and the chain solver's speed
/// against error (ScopeSweep.h), and the full procedure loop step rate
/// (ProcedureRate.h).
///
/// Writes into outDir: speed_vs_error.csv, speed_vs_error.svg,
/// scope_speed_vs_error.csv, summary.json.
/// Scales: full (0.2 s scene, 1 s active-region run, 3.5 s of procedure
/// warm-up) and quick (0.01 s, 0.1 s and 0.2 s, fewer bisection steps,
/// shorter timings) for tests and smoke runs; the scope sweep's errors are
/// the same at both scales.

#include <filesystem>
#include <iosfwd>

namespace colonosim::bench {

struct BenchReportOptions {
    bool quick = false;
    std::filesystem::path outDir;
};

/// Runs the report; progress and figures go to `log`. Returns 0 on success,
/// 1 when the output could not be written (the reason is logged).
int runBenchReport(const BenchReportOptions& options, std::ostream& log);

}  // namespace colonosim::bench
