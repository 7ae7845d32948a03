// The tissue's topology stays editable while it runs (for snare cutting to
// come): nodes can be appended and springs added and removed locally, without
// rebuilding the body, and the scene goes on stably after a replan.

#include "TubeAnatomy.h"

#include "simcore/physics/ColonBody.h"
#include "simcore/physics/TissueSimulation.h"

#include <gtest/gtest.h>

namespace colonosim::physics {
namespace {

TEST(TopologyEdit, AppendANodeAndCutSpringsWhileRunning)
{
    TubeResolution tube;
    tube.rings = 12;
    ColonBody colon = buildColonBody(testing::makeTubeAnatomy(tube), TissueParameters{},
                                     EnvironmentParameters{}, {0.6, 0.95});
    TissueSimulation simulation(colon.body, SteppingPolicy{});
    for (int s = 0; s < 50; ++s) {
        simulation.advance();
    }
    const int springsBefore = colon.springs->numSprings();

    // A lesion node hung 5 mm inside the wall from three wall nodes.
    const int a = 8 * 16;
    const int b = 8 * 16 + 1;
    const int c = 9 * 16;
    const Eigen::Vector3d centre =
        (colon.body.positions().col(a) + colon.body.positions().col(b) + colon.body.positions().col(c)) / 3.0;
    const Eigen::Vector3d inward = -Eigen::Vector3d(centre.x(), centre.y(), 0.0).normalized();
    const int lesion = colon.body.addNode(centre + 0.005 * inward, 2e-4);
    for (const int wall : {a, b, c}) {
        const double rest = (colon.body.positions().col(lesion) - colon.body.positions().col(wall)).norm();
        colon.springs->add(lesion, wall, rest, 500.0, 500.0 * TissueParameters{}.dampingTime);
    }
    // Cut every spring of one wall node (a snare through the wall).
    const int cut = 10 * 16 + 5;
    for (int s = colon.springs->numSprings() - 1; s >= 0; --s) {
        if (colon.springs->nodeA(s) == cut || colon.springs->nodeB(s) == cut) {
            colon.springs->remove(s);
        }
    }
    EXPECT_EQ(colon.body.numNodes(), tube.rings * tube.nodesPerRing + 1);
    EXPECT_LT(colon.springs->numSprings(), springsBefore + 3) << "springs of the cut node removed";
    for (int s = 0; s < colon.springs->numSprings(); ++s) {
        EXPECT_NE(colon.springs->nodeA(s), cut);
        EXPECT_NE(colon.springs->nodeB(s), cut);
    }

    // The new node feels gravity and drag like any other: gravity and drag
    // follow the body's masses.
    {
        Forces f;
        const Velocities still = Velocities::Zero(3, colon.body.numNodes());
        colon.body.computeForces(colon.body.positions(), still, f);
        Forces springsOnly = Forces::Zero(3, colon.body.numNodes());
        colon.springs->addForce(colon.body.positions(), springsOnly);
        const Eigen::Vector3d weight = 2e-4 * 9.81 * downDirection(EnvironmentParameters{}.patientPosition);
        EXPECT_LT((f.col(lesion) - springsOnly.col(lesion) - weight).norm(), 1e-12);
    }

    simulation.replan();
    const Eigen::Vector3d lesionStart = colon.body.positions().col(lesion);
    for (int s = 0; s < 300; ++s) {
        simulation.advance();
    }
    EXPECT_EQ(simulation.rejectedSteps(), 0) << simulation.planNote();
    EXPECT_TRUE(colon.body.positions().allFinite());
    EXPECT_LT((colon.body.positions().col(lesion) - lesionStart).norm(), 0.02)
        << "the lesion stays held by its springs";
}

}  // namespace
}  // namespace colonosim::physics
