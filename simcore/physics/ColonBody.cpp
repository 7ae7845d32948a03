#include "simcore/physics/ColonBody.h"

#include "simcore/geometry/CentrelineSampling.h"

#include "simcore/physics/Gravity.h"
#include "simcore/physics/LumenSelfContact.h"
#include "simcore/physics/OrganConstraint.h"
#include "simcore/physics/ViscousDrag.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace colonosim::physics {

using geometry::Attachment;
using geometry::ColonAnatomy;

namespace {
std::vector<std::vector<int>> springNeighbours(const SpringSet& springs, int numNodes)
{
    std::vector<std::vector<int>> neighbours(static_cast<size_t>(numNodes));
    for (int s = 0; s < springs.numSprings(); ++s) {
        neighbours[static_cast<size_t>(springs.nodeA(s))].push_back(springs.nodeB(s));
        neighbours[static_cast<size_t>(springs.nodeB(s))].push_back(springs.nodeA(s));
    }
    for (auto& list : neighbours) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return neighbours;
}
}  // namespace

ColonBody buildColonBody(const ColonAnatomy& anatomy, const TissueParameters& tissue,
                         const EnvironmentParameters& environment, const StiffnessCalibration& calibration,
                         const ColonBodyOptions& options)
{
    tissue.validate();
    environment.validate();
    const geometry::TriangleMesh& mesh = anatomy.physicsMesh;
    const int n = mesh.numVertices();
    if (static_cast<int>(anatomy.physicsNodes.size()) != n) {
        throw std::invalid_argument("buildColonBody: one PhysicsNodeInfo per physics vertex is required");
    }
    if (anatomy.centreline.numPoints() < 2) {
        throw std::invalid_argument("buildColonBody: the anatomy has no centreline");
    }

    std::vector<Eigen::Vector3d> axis(static_cast<size_t>(n));
    std::vector<double> radius(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const geometry::CentrelineSample at = geometry::sampleCentreline(
            anatomy.centreline, anatomy.physicsNodes[static_cast<size_t>(i)].arcLength);
        axis[static_cast<size_t>(i)] = at.tangent;
        radius[static_cast<size_t>(i)] = at.radius;
    }

    const Eigen::VectorXd mass = wallNodeMasses(mesh, tissue);
    ColonBody colon{
        TissueBody(mesh.vertices, mass), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, {}};
    TissueBody& body = colon.body;

    auto springs = std::make_unique<SpringSet>("wall");
    addWallSprings(mesh, axis, tissue, calibration, *springs);
    springs->setTransverseDamping(tissue.transverseDampingRatio);
    colon.neighbours = springNeighbours(*springs, n);
    colon.springs = static_cast<SpringSet*>(&body.addForceTerm(std::move(springs)));

    auto mesentery = std::make_unique<Mesentery>();
    auto retro = std::make_unique<AnchorSprings>("retroperitoneal");
    const double beta = tissue.dampingTime;
    const Mesentery::Law baseLaw{0.0, 0.0, tissue.mesenteryStiffeningStrain, tissue.mesenteryMaxStrain};
    for (int i = 0; i < n; ++i) {
        const geometry::PhysicsNodeInfo& info = anatomy.physicsNodes[static_cast<size_t>(i)];
        switch (info.attachment) {
        case Attachment::Fixed: body.setFixed(i, true); break;
        case Attachment::Retroperitoneal:
            retro->add(i, mesh.vertices.col(i), tissue.retroperitonealStiffness,
                       beta * tissue.retroperitonealStiffness);
            break;
        case Attachment::Mesenteric: {
            const double length = (mesh.vertices.col(i) - info.mesenteryRoot).norm();
            if (length <= 1e-6) {
                throw std::invalid_argument("buildColonBody: node " + std::to_string(i) +
                                            " has its mesentery root at the node itself");
            }
            const double wallArea = mass[i] / (tissue.wallDensity * tissue.wallThickness);
            const double sheet = tissue.mesenteryThickness * wallArea /
                                 (2.0 * std::numbers::pi * radius[static_cast<size_t>(i)]);
            Mesentery::Law law = baseLaw;
            law.stiffness = tissue.mesenteryModulus * sheet / length;
            law.damping = beta * law.stiffness;
            mesentery->add(i, info.mesenteryRoot, length, law);
            break;
        }
        }
    }
    colon.mesentery = static_cast<Mesentery*>(&body.addForceTerm(std::move(mesentery)));
    colon.retroperitoneal = static_cast<AnchorSprings*>(&body.addForceTerm(std::move(retro)));

    auto adhesions = std::make_unique<AnchorSprings>("adhesions");
    for (const int node : options.adhesionNodes) {
        if (node < 0 || node >= n) {
            throw std::invalid_argument("buildColonBody: adhesion node " + std::to_string(node) +
                                        " is not in [0, " + std::to_string(n - 1) + "]");
        }
        adhesions->add(node, mesh.vertices.col(node), tissue.adhesionStiffness,
                       beta * tissue.adhesionStiffness);
    }
    colon.adhesions = static_cast<AnchorSprings*>(&body.addForceTerm(std::move(adhesions)));

    if (tissue.surroundingDampingRate > 0.0) {
        body.addForceTerm(std::make_unique<ViscousDrag>(mass, tissue.surroundingDampingRate));
    }
    if (options.withGravity && environment.gravity > 0.0) {
        body.addForceTerm(std::make_unique<Gravity>(mass, environment.gravity *
                                                              downDirection(environment.patientPosition)));
    }
    if (options.withInsufflation) {
        colon.insufflation = static_cast<InsufflationPressure*>(&body.addForceTerm(
            std::make_unique<InsufflationPressure>(mesh.triangles, environment.insufflationPressure)));
    }
    if (tissue.selfContactStiffness > 0.0) {
        std::vector<double> arcs(static_cast<size_t>(n));
        for (size_t i = 0; i < arcs.size(); ++i) {
            arcs[i] = anatomy.physicsNodes[i].arcLength;
        }
        std::vector<LumenSelfContact::Ring> rings = lumenRings(mesh.vertices, arcs);
        if (rings.size() >= 2) {
            colon.selfContact =
                static_cast<LumenSelfContact*>(&body.addForceTerm(std::make_unique<LumenSelfContact>(
                    std::move(rings), tissue.selfContactStiffness, mesh.vertices)));
        }
    }
    if (options.withOrgans && !anatomy.organs.empty()) {
        body.addConstraint(std::make_unique<OrganConstraint>(anatomy.organs));
    }
    return colon;
}

}  // namespace colonosim::physics
