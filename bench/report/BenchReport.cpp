#include "bench/report/BenchReport.h"

#include "bench/report/ActiveRegionStudy.h"
#include "bench/report/BenchScene.h"
#include "bench/report/BulletPeer.h"
#include "bench/report/ProcedureRate.h"
#include "bench/report/SceneRun.h"
#include "bench/report/ScopeSweep.h"
#include "bench/report/SpeedErrorSweep.h"
#include "bench/report/SpeedVsErrorPlot.h"
#include "bench/report/StepRate.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <string>
#include <thread>

namespace colonosim::bench {

namespace {

struct Scale {
    double sceneDuration;   ///< s simulated per sweep run
    double activeDuration;  ///< s simulated per active-region run
    double rateSeconds;     ///< CPU s per step-rate timing
    int mappingRepeats;
    int bisectionHalvings;   ///< on Bullet's kLST
    TimingScale scopeStep;   ///< scope_step_us
    TimingScale scopeSweep;  ///< each row of the scope sweep
    int procedureWarmup;     ///< expert steps before the procedure timing
    int procedureTimed;      ///< timed procedure steps
};

constexpr Scale kFull{0.2, 1.0, 1.0, 200, 14, {0.02, 51}, {0.01, 21}, 3500, 2000};
constexpr Scale kQuick{0.01, 0.1, 0.2, 30, 8, {0.002, 11}, {0.001, 5}, 200, 100};

struct PeerResult {
    BulletMatch match;
    double stepHz = 0.0;
    double cpuPerSimulatedSecond = 0.0;
    PositionError error;
};

PeerResult runPeer(const BenchScene& scene, const Scale& scale, double duration,
                   const ReferenceSolution& reference, std::ostream& log)
{
    PeerResult peer;
    peer.match = matchBulletStiffness(scene, scale.bisectionHalvings, log);
    BulletSettings settings = peer.match.settings;
    settings.damping = 0.0;
    BulletColon colon(scene, settings);
    constexpr double h = 1e-3;
    const long steps = std::max(1L, std::lround(duration / h));
    const double start = processCpuSeconds();
    for (long s = 0; s < steps; ++s) {
        colon.step((static_cast<double>(s) + 0.5) * h, h, true);
    }
    const double cpu = processCpuSeconds() - start;
    peer.stepHz = static_cast<double>(steps) / cpu;
    peer.cpuPerSimulatedSecond = cpu / (static_cast<double>(steps) * h);
    peer.error = positionError(colon.positions(), reference.positions);
    log << "peer: bullet_btSoftBody at 1 ms: " << peer.stepHz << " steps/s; error vs reference rms "
        << peer.error.rms << " m, max " << peer.error.max << " m\n";
    return peer;
}

std::string cpuModel()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown";
}

/// JSON number, or null when not finite.
nlohmann::json number(double value)
{
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json scopeSweepJson(const std::vector<ScopeSweepRow>& rows)
{
    nlohmann::json out = nlohmann::json::array();
    for (const ScopeSweepRow& row : rows) {
        out.push_back({{"nodes", row.nodes},
                       {"inserted_nodes", row.insertedNodes},
                       {"iterations", row.iterations},
                       {"step_us", row.stepSeconds * 1e6},
                       {"tip_error_m", number(row.tipError)},
                       {"max_node_error_m", number(row.maxNodeError)},
                       {"tip_iteration_error_m", number(row.iterationTipError)},
                       {"fixed_point_tip_error_m", number(row.fixedPointTipError)},
                       {"discretisation_tip_error_m", number(row.discretisationTipError)},
                       {"total_tip_error_m", number(row.totalTipError)}});
    }
    return out;
}

}  // namespace

int runBenchReport(const BenchReportOptions& options, std::ostream& log)
{
    const Scale scale = options.quick ? kQuick : kFull;
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec) {
        log << "bench report: cannot create " << options.outDir << ": " << ec.message() << "\n";
        return 1;
    }
    const double start = processCpuSeconds();
    const BenchScene scene = buildBenchScene();
    log << "scene: " << scene.anatomy.physicsMesh.numVertices() << " physics nodes, "
        << scene.anatomy.visualMesh.numVertices() << " visual vertices, " << scene.load.nodes.size()
        << " loaded nodes; " << (options.quick ? "quick" : "full") << " scale, " << scale.sceneDuration
        << " s simulated per run\n";

    nlohmann::json summary = nlohmann::json::object();
    summary["quick"] = options.quick;
    summary["machine"] = {{"cpu", cpuModel()},
                          {"hardware_threads", std::thread::hardware_concurrency()},
                          {"threads_used", 1},
                          {"compiler", __VERSION__}};
    summary["nodes"] = scene.anatomy.physicsMesh.numVertices();
    summary["visual_vertices"] = scene.anatomy.visualMesh.numVertices();
    summary["scene_duration_s"] = scale.sceneDuration;

    nlohmann::json stepHz = nlohmann::json::object();
    nlohmann::json stableStep = nlohmann::json::object();
    for (const physics::IntegratorKind kind : physics::kAllIntegrators) {
        const std::string name(physics::integratorName(kind));
        stepHz[name] = measureColonStepHz(scene, kind, scale.rateSeconds);
        stableStep[name] = benchStableStep(scene, kind);
        log << "colon step: " << name << " " << stepHz[name].get<double>() << " steps/s at "
            << stableStep[name].get<double>() * 1e6 << " us\n";
    }
    summary["colon_step_hz"] = stepHz;
    summary["stable_step_s"] = stableStep;
    summary["mapping_54k_ms"] = 1e3 * measureMappingSeconds(scene, scale.mappingRepeats);
    log << "mapping: " << summary["mapping_54k_ms"].get<double>() << " ms (median)\n";

    const scope::ScopeParameters paperScope;  // 80 nodes, 50 iterations
    summary["scope_step_us"] = 1e6 * measureScopeStepSeconds(paperScope, ScopeLoad::Free, scale.scopeStep);
    log << "scope step: " << summary["scope_step_us"].get<double>()
        << " us (80 nodes, 50 iterations, median)\n";
    const std::vector<ScopeSweepRow> scopeRows = runScopeSweep({.timing = scale.scopeSweep}, log);
    summary["scope_speed_vs_error"] = scopeSweepJson(scopeRows);

    const ProcedureRate procedure = measureProcedureStepRate(scale.procedureWarmup, scale.procedureTimed);
    summary["procedure_step_hz"] = procedure.stepHz;
    summary["procedure_step"] = {{"substeps", procedure.substeps},
                                 {"warmup_steps", procedure.warmupSteps},
                                 {"timed_steps", procedure.timedSteps},
                                 {"operator", "expert"}};
    log << "procedure step: " << procedure.stepHz << " steps/s, " << procedure.substeps << " substeps (after "
        << procedure.warmupSteps << " expert steps)\n";

    const ReferenceSolution reference = computeReference(scene, scale.sceneDuration, log);
    summary["reference_self_error_m"] = number(reference.selfError);
    summary["reference_self_error_max_m"] = number(reference.selfErrorMax);
    summary["reference_step_s"] = reference.step;
    const std::vector<SweepRow> rows = runSpeedErrorSweep(scene, scale.sceneDuration, reference, log);

    const PeerResult peer = runPeer(scene, scale, scale.sceneDuration, reference, log);
    summary["peer"] = {{"name", "bullet_btSoftBody"},
                       {"colon_step_hz", peer.stepHz},
                       {"step_s", 1e-3},
                       {"rms_error_m", number(peer.error.rms)},
                       {"max_error_m", number(peer.error.max)},
                       {"kLST", peer.match.settings.linearStiffness},
                       {"piterations", peer.match.settings.positionIterations},
                       {"static_deflection_ours_m", peer.match.targetDeflection},
                       {"static_deflection_peer_m", peer.match.peerDeflection},
                       {"matching", peer.match.note}};

    const ActiveRegionResult active = runActiveRegionStudy(scene, scale.activeDuration, log);
    summary["active_region"] = {{"speedup", number(active.speedup)},
                                {"rms_error_m", number(active.rmsError)},
                                {"max_error_m", number(active.maxError)},
                                {"awake_fraction", active.awakeFraction},
                                {"final_awake_fraction", active.finalAwakeFraction},
                                {"duration_s", active.duration},
                                {"integrator", "symplectic_euler"}};

    std::ofstream csv(options.outDir / "speed_vs_error.csv");
    writeSweepCsv(rows, csv);
    std::ofstream scopeCsv(options.outDir / "scope_speed_vs_error.csv");
    writeScopeSweepCsv(scopeRows, scopeCsv);
    std::ofstream svg(options.outDir / "speed_vs_error.svg");
    writeSpeedVsErrorSvg(rows, PeerPoint{"bullet_btSoftBody", peer.cpuPerSimulatedSecond, peer.error.rms},
                         "Colon, " +
                             std::to_string(static_cast<int>(std::lround(scale.sceneDuration * 1e3))) +
                             " ms loaded: error vs cost",
                         svg);
    summary["report_cpu_s"] = processCpuSeconds() - start;
    std::ofstream json(options.outDir / "summary.json");
    json << summary.dump(2) << "\n";
    if (!csv || !scopeCsv || !svg || !json) {
        log << "bench report: writing into " << options.outDir << " failed\n";
        return 1;
    }
    log << "bench report: wrote speed_vs_error.csv, speed_vs_error.svg, scope_speed_vs_error.csv, "
           "summary.json into "
        << options.outDir << " (" << summary["report_cpu_s"].get<double>() << " s CPU)\n";
    return 0;
}

}  // namespace colonosim::bench
