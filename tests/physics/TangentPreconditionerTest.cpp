// The static solver's preconditioner: -K+ recovered by probing a coloured
// set of nodes at a time, and factored.

#include "simcore/physics/TangentPreconditioner.h"
#include "TubeAnatomy.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/StaticSolver.h"

#include <gtest/gtest.h>

#include <random>

namespace colonosim::physics {
namespace {

/// A random displacement on the integrated nodes (zero elsewhere), m.
Eigen::Matrix3Xd randomOnIntegrated(const TissueBody& body, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, 1e-3);
    Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, body.numNodes());
    for (const int i : body.integratedNodes()) {
        v.col(i) = Eigen::Vector3d(normal(random), normal(random), normal(random));
    }
    return v;
}

/// With every coupling declared (the wall's springs; the mesentery, the
/// anchors and gravity act on each node alone) the probed matrix is the
/// operator itself: the preconditioner inverts -K+ exactly. A colouring that
/// let two nodes of one colour share a neighbour would mix their columns.
void expectExactInverse(const TissueBody& body, int maxColours)
{
    TangentPreconditioner preconditioner;
    ASSERT_TRUE(preconditioner.build(body));
    EXPECT_GT(preconditioner.colours(), 1);
    EXPECT_LE(preconditioner.colours(), maxColours) << "a local stencil needs few colours";
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const Eigen::Matrix3Xd v = randomOnIntegrated(body, seed);
        Eigen::Matrix3Xd kv;
        body.stiffnessProduct(body.positions(), v, kv, true);
        Eigen::Matrix3Xd z;
        preconditioner.apply(-kv, z);
        EXPECT_LT((z - v).norm(), 1e-8 * v.norm()) << "seed " << seed;
    }
}

TEST(TangentPreconditioner, InvertsTheStiffnessOfAStraightTube)
{
    TubeResolution tube;
    tube.rings = 16;
    const ColonBody colon = buildColonBody(testing::makeTubeAnatomy(tube), TissueParameters{},
                                           EnvironmentParameters{}, {0.6, 0.95}, {true, false, false, {}});
    expectExactInverse(colon.body, 64);
}

// The same on the default colon, bent and sagging at its equilibrium under
// gravity and insufflation (the state the procedure starts from), where the
// springs are stretched and compressed and K+ drops their compressed
// transverse terms (insufflation, a follower load, is not in K+).
TEST(TangentPreconditioner, InvertsTheStiffnessOfTheDefaultColonAtRest)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    ColonBody colon =
        buildColonBody(anatomy, TissueParameters{}, EnvironmentParameters{}, StiffnessCalibration{});
    const StaticResult rest = solveStaticEquilibrium(colon.body, 1e-5, 1000);
    ASSERT_TRUE(rest.converged);
    expectExactInverse(colon.body, 64);
}

}  // namespace
}  // namespace colonosim::physics
