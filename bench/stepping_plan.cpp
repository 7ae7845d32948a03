// Stepping plan report: for each patient, the colon's stable-step plan at
// rest as the procedure loop makes it (symplectic Euler substeps from the
// Gershgorin bound, physics/StabilityBound.h) against what power iteration
// finds for the highest mode: its frequency and the damping ratio that the
// wall's stiffness-proportional damping (tissue.dampingTime) gives it. Seed 0
// is the default colon; others are generated patients (bench/PatientFromSeed.h).
// The node columns give each node's own Gershgorin frequency, sqrt(kRow_i /
// m_i), at its 10th, 50th and 90th percentile over the nodes: how much of
// the colon could take a longer step than its stiffest node (the question a
// multirate scheme asks).
//
//   stepping_plan [--seeds 0,1,2,...] [--iterations N]
//
// About 1 s a patient at the default 3,000 power iterations.

#include "bench/ListArgument.h"
#include "bench/PatientFromSeed.h"
#include "simcore/physics/StabilityBound.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace colonosim;

int main(int argc, char** argv)
{
    std::vector<std::uint64_t> seeds{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    int iterations = 3000;
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            if (flag == "--seeds") {
                seeds = bench::parseSeeds(flag, value);
            } else if (flag == "--iterations") {
                iterations = static_cast<int>(bench::parseList(flag, value, 10.0, 100000.0).front());
            } else {
                throw std::invalid_argument("unknown option '" + flag + "' (allowed: --seeds, --iterations)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stepping_plan: %s\n", error.what());
        return 2;
    }
    std::printf(
        "seed: 0 the default colon; bound: Gershgorin's omega_max (rad/s); stable: the damped "
        "stable step it gives (us); top: the highest mode by %d power iterations (rad/s, from "
        "below) and its damping ratio; node q10/q50/q90: the nodes' own bounds sqrt(kRow/m) (rad/s)\n",
        iterations);
    std::printf("%-6s %8s %10s %10s %10s %8s %9s %9s %9s\n", "seed", "substeps", "stable_us", "bound", "top",
                "zeta", "node_q10", "node_q50", "node_q90");
    for (const std::uint64_t seed : seeds) {
        const bench::Patient patient = bench::patientFromSeed(seed);
        const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(patient.anatomy);
        const procedure::ProcedureLoop loop(anatomy, patient.settings);
        const physics::TissueSimulation& tissue = loop.tissue();
        const physics::TopMode top = physics::powerIterationTopMode(loop.colon().body, iterations);
        Eigen::VectorXd kRow;
        Eigen::VectorXd cRow;
        (void)physics::estimateStability(loop.colon().body, kRow, cRow);
        const Eigen::VectorXd& masses = loop.colon().body.masses();
        std::vector<double> own;
        for (Eigen::Index i = 0; i < kRow.size(); ++i) {
            if (masses[i] > 0.0 && kRow[i] > 0.0) {
                own.push_back(std::sqrt(kRow[i] / masses[i]));
            }
        }
        std::sort(own.begin(), own.end());
        const auto quantile = [&own](double q) {
            return own.empty() ? 0.0
                               : own[std::min(own.size() - 1,
                                              static_cast<size_t>(q * static_cast<double>(own.size())))];
        };
        std::printf("%-6llu %8d %10.1f %10.0f %10.0f %8.3f %9.0f %9.0f %9.0f\n",
                    static_cast<unsigned long long>(seed), tissue.substeps(), tissue.stableStep() * 1e6,
                    tissue.stability().omegaMax, top.omega, top.dampingRatio, quantile(0.1), quantile(0.5),
                    quantile(0.9));
        std::fflush(stdout);
    }
    return 0;
}
