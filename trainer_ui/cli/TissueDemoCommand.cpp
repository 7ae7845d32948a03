/// \file
/// `colonosim demo --tissue`: a headless demonstration of the simulator's foundation. It builds
/// the default procedural colon, calibrates the wall, settles it under
/// gravity and insufflation, pushes on the sigmoid wall as a colonoscope
/// would, maps the visual mesh, and reports what happened in physical units.

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/MeshMapping.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ActiveRegion.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/SpringCalibration.h"
#include "simcore/physics/TissueSimulation.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>

namespace colonosim::cli {

namespace {
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since)
{
    return std::chrono::duration<double>(Clock::now() - since).count();
}

/// The physics node of the sigmoid nearest the middle of the segment.
int sigmoidNode(const geometry::ColonAnatomy& anatomy)
{
    double first = 1e9;
    double last = -1e9;
    for (const auto& info : anatomy.physicsNodes) {
        if (info.segment == geometry::Segment::Sigmoid) {
            first = std::min(first, info.arcLength);
            last = std::max(last, info.arcLength);
        }
    }
    const double middle = 0.5 * (first + last);
    int best = 0;
    for (int i = 0; i < static_cast<int>(anatomy.physicsNodes.size()); ++i) {
        if (std::abs(anatomy.physicsNodes[static_cast<size_t>(i)].arcLength - middle) <
            std::abs(anatomy.physicsNodes[static_cast<size_t>(best)].arcLength - middle)) {
            best = i;
        }
    }
    return best;
}
}  // namespace

int runTissueDemo(std::span<char* const> args)
{
    const CommandLine line(args, {"--json", "--help"}, {"--duration", "--integrator"});
    if (line.has("--help")) {
        std::cout << "usage: colonosim demo --tissue [--duration S] [--integrator NAME] [--json]\n"
                     "Tissue demonstration: procedural colon, wall calibration, settling under gravity and\n"
                     "insufflation, a 2 N push on the sigmoid wall, visual-mesh mapping.\n"
                     "  --duration S      simulated seconds, 0.05-60 (default 0.5)\n"
                     "  --integrator NAME explicit_euler, symplectic_euler (default), rk4, backward_euler\n";
        return 0;
    }
    const double duration = line.number("--duration", 0.5, 0.05, 60.0, "s");
    physics::SteppingPolicy policy;
    policy.integrator = physics::parseIntegrator(line.value("--integrator").value_or("symplectic_euler"));
    const bool json = line.has("--json");
    std::ostream& log = json ? std::cerr : std::cout;

    auto start = Clock::now();
    const geometry::AnatomyParameters anatomyParameters;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(anatomyParameters);
    log << "colon: " << anatomy.centreline.length() << " m, " << anatomy.physicsMesh.numVertices()
        << " physics nodes, " << anatomy.visualMesh.numVertices() << " visual vertices, "
        << anatomy.organs.size() << " organs (" << seconds(start) << " s)\n";

    const physics::TissueParameters tissue;
    const physics::EnvironmentParameters environment;
    physics::TubeResolution tube;
    tube.nodesPerRing = static_cast<int>(anatomyParameters.physicsNodesPerRing);
    tube.radius = 0.5 * anatomyParameters.diameter(geometry::Segment::Sigmoid);
    tube.ringSpacing =
        anatomyParameters.totalLength() * tube.nodesPerRing / anatomyParameters.physicsTargetNodeCount;
    const physics::CalibrationReport calibration = physics::calibrateWallStiffness(tube, tissue);
    log << "wall calibration: axial x" << calibration.factors.axial << ", circumferential x"
        << calibration.factors.circumferential << " (residual " << calibration.axialStiffnessError << ", "
        << calibration.hoopStiffnessError << ")\n";

    physics::ColonBody colon = physics::buildColonBody(anatomy, tissue, environment, calibration.factors);
    physics::TissueSimulation simulation(colon.body, policy);
    physics::ActiveRegion region(colon.neighbours, physics::SleepParameters{});
    simulation.setActiveRegion(&region);
    log << "stepping: " << simulation.planNote() << '\n';

    const physics::Positions rest = colon.body.positions();
    const int pushed = sigmoidNode(anatomy);
    const Eigen::Vector3d pushCentre =
        geometry::sampleCentreline(anatomy.centreline,
                                   anatomy.physicsNodes[static_cast<size_t>(pushed)].arcLength)
            .point;
    const int steps = static_cast<int>(std::lround(duration / policy.loopStep));
    start = Clock::now();
    for (int s = 0; s < steps; ++s) {
        colon.body.clearExternalForces();
        if (s >= steps / 2) {
            // A colonoscope tip pushing the sigmoid wall outward with 2 N,
            // spread over the node and its spring neighbours (~2 cm across).
            const Eigen::Vector3d outward = (rest.col(pushed) - pushCentre).normalized();
            const auto& patch = colon.neighbours[static_cast<size_t>(pushed)];
            const double share = 2.0 / static_cast<double>(patch.size() + 1);
            colon.body.applyExternalForce(pushed, share * outward);
            for (const int node : patch) {
                colon.body.applyExternalForce(node, share * outward);
            }
        }
        simulation.advance();
    }
    const double wall = seconds(start);
    double maxDisplacement = 0.0;
    for (Eigen::Index i = 0; i < rest.cols(); ++i) {
        maxDisplacement = std::max(maxDisplacement, (colon.body.positions().col(i) - rest.col(i)).norm());
    }
    const double pushDisplacement = (colon.body.positions().col(pushed) - rest.col(pushed)).norm();

    start = Clock::now();
    const geometry::MeshMapping mapping(anatomy.physicsMesh, anatomy.visualMesh.vertices);
    const double mappingBuild = seconds(start);
    Eigen::Matrix3Xd visual(3, anatomy.visualMesh.numVertices());
    start = Clock::now();
    mapping.apply(colon.body.positions(), visual);
    const double mappingApply = seconds(start);

    log << "simulated " << duration << " s in " << steps << " loop steps: " << wall << " s wall ("
        << duration / wall << "x real time); " << region.numAwake() << " of " << colon.body.numNodes()
        << " nodes awake at the end\n"
        << "pushed node moved " << pushDisplacement * 1e3 << " mm; largest displacement "
        << maxDisplacement * 1e3 << " mm; mesentery strain up to "
        << colon.mesentery->maxStrain(colon.body.positions()) << "\n"
        << "rejected steps: " << simulation.rejectedSteps() << '\n'
        << "visual mapping: built in " << mappingBuild << " s, applied in " << mappingApply * 1e3 << " ms\n";
    for (const auto& rejection : simulation.rejections()) {
        log << "  " << rejection.message << '\n';
    }
    if (json) {
        nlohmann::json out;
        out["colon_length_m"] = anatomy.centreline.length();
        out["physics_nodes"] = anatomy.physicsMesh.numVertices();
        out["visual_vertices"] = anatomy.visualMesh.numVertices();
        out["stepping"] = simulation.planNote();
        out["simulated_s"] = duration;
        out["wall_s"] = wall;
        out["push_displacement_m"] = pushDisplacement;
        out["max_displacement_m"] = maxDisplacement;
        out["rejected_steps"] = simulation.rejectedSteps();
        out["awake_nodes"] = region.numAwake();
        out["mapping_apply_ms"] = mappingApply * 1e3;
        std::cout << out.dump(2) << '\n';
    }
    return simulation.rejectedSteps() == 0 ? 0 : 1;
}

}  // namespace colonosim::cli
