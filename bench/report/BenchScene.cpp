#include "bench/report/BenchScene.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/SpringCalibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace colonosim::bench {

using geometry::Segment;

Eigen::Vector3d StandardLoad::nodeForce(double t) const
{
    if (nodes.empty()) {
        return Eigen::Vector3d::Zero();
    }
    const double ramp = rampTime > 0.0 ? std::clamp(t / rampTime, 0.0, 1.0) : 1.0;
    return (totalForce * ramp / static_cast<double>(nodes.size())) * direction;
}

void StandardLoad::apply(physics::TissueBody& body, double t) const
{
    body.clearExternalForces();
    const Eigen::Vector3d f = nodeForce(t);
    for (const int node : nodes) {
        body.applyExternalForce(node, f);
    }
}

namespace {

/// Tube resolution matching the colon's physics mesh: its ring size, mean
/// lumen radius over the nodes and mean ring spacing.
physics::TubeResolution matchingTube(const geometry::ColonAnatomy& anatomy, int nodesPerRing)
{
    double radiusSum = 0.0;
    for (const geometry::PhysicsNodeInfo& info : anatomy.physicsNodes) {
        radiusSum += geometry::sampleCentreline(anatomy.centreline, info.arcLength).radius;
    }
    const int n = anatomy.physicsMesh.numVertices();
    physics::TubeResolution tube;
    tube.nodesPerRing = nodesPerRing;
    tube.radius = radiusSum / n;
    tube.ringSpacing = anatomy.centreline.length() / (static_cast<double>(n) / nodesPerRing);
    return tube;
}

StandardLoad placeStandardLoad(const geometry::ColonAnatomy& anatomy, const physics::TissueBody& body)
{
    double sMin = std::numeric_limits<double>::infinity();
    double sMax = -sMin;
    for (const geometry::PhysicsNodeInfo& info : anatomy.physicsNodes) {
        if (info.segment == Segment::Sigmoid) {
            sMin = std::min(sMin, info.arcLength);
            sMax = std::max(sMax, info.arcLength);
        }
    }
    if (!(sMax >= sMin)) {
        throw std::runtime_error("bench scene: the colon has no sigmoid nodes");
    }
    const double sMid = 0.5 * (sMin + sMax);
    int centre = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < body.numNodes(); ++i) {
        const geometry::PhysicsNodeInfo& info = anatomy.physicsNodes[static_cast<size_t>(i)];
        const double distance = std::abs(info.arcLength - sMid) + 1e-3 * std::abs(info.angle);
        if (info.segment == Segment::Sigmoid && !body.isFixed(i) && distance < best) {
            best = distance;
            centre = i;
        }
    }
    StandardLoad load;
    load.point = body.positions().col(centre);
    const geometry::PhysicsNodeInfo& info = anatomy.physicsNodes[static_cast<size_t>(centre)];
    const Eigen::Vector3d axisPoint = geometry::sampleCentreline(anatomy.centreline, info.arcLength).point;
    load.direction = (load.point - axisPoint).normalized();
    for (int i = 0; i < body.numNodes(); ++i) {
        if (!body.isFixed(i) && (body.positions().col(i) - load.point).norm() <= load.radius) {
            load.nodes.push_back(i);
        }
    }
    return load;
}

}  // namespace

physics::ColonBody BenchScene::makeBody() const
{
    return physics::buildColonBody(anatomy, tissue, environment, calibration);
}

BenchScene buildBenchScene()
{
    BenchScene scene;
    scene.anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    scene.environment.patientPosition = physics::PatientPosition::LeftLateral;
    scene.environment.insufflationPressure = 2000.0;  // 15 mmHg
    const int perRing = static_cast<int>(geometry::AnatomyParameters{}.physicsNodesPerRing);
    scene.calibration =
        physics::calibrateWallStiffness(matchingTube(scene.anatomy, perRing), scene.tissue).factors;
    const physics::ColonBody body = scene.makeBody();
    scene.load = placeStandardLoad(scene.anatomy, body.body);
    return scene;
}

}  // namespace colonosim::bench
