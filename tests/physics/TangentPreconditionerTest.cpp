// The static solver's preconditioner: -K+ recovered by probing a coloured
// set of nodes at a time, and factored.

#include "simcore/physics/TangentPreconditioner.h"
#include "TubeAnatomy.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/LumenSelfContact.h"
#include "simcore/physics/StaticSolver.h"
#include "tests/physics/ColonRings.h"

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

// A self-contact's couplings come and go with the state and are not
// declared: probing it would put a ring's contact blocks into the columns of
// other nodes of the same colour. The preconditioner probes only the declared
// terms, so it still inverts them exactly while the contact acts (generated
// patient 7 overlaps itself at rest; RestStateTest.cpp has the whole solve).
TEST(TangentPreconditioner, LeavesOutTheSelfContactWhoseCouplingsAreNotDeclared)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    ColonBody colon =
        buildColonBody(anatomy, TissueParameters{}, EnvironmentParameters{}, StiffnessCalibration{});
    ASSERT_NE(colon.selfContact, nullptr);
    EXPECT_FALSE(colon.selfContact->couplingsDeclared());
    // The sigmoid's ring at 0.342 m moved 15 mm towards the transverse
    // colon's at 1.091 m (44.5 mm apart, reach about 37 mm; LumenSelfContactTest.cpp).
    const LumenSelfContact::Ring a = testing::ringNearest(anatomy, 0.342);
    const LumenSelfContact::Ring b = testing::ringNearest(anatomy, 1.091);
    const auto centre = [&](const LumenSelfContact::Ring& ring) {
        return testing::ringCentre(colon.body.positions(), ring);
    };
    const Eigen::Vector3d shift = (centre(b) - centre(a)).normalized() * 15e-3;
    for (const int node : a.nodes) {
        colon.body.positions().col(node) += shift;
    }
    ASSERT_GT(colon.selfContact->overlappingPairs(colon.body.positions()), 0);

    TangentPreconditioner preconditioner;
    ASSERT_TRUE(preconditioner.build(colon.body));
    const Eigen::Matrix3Xd v = randomOnIntegrated(colon.body, 4);
    Eigen::Matrix3Xd declared;
    colon.body.declaredStiffnessProduct(colon.body.positions(), v, declared);
    Eigen::Matrix3Xd z;
    preconditioner.apply(-declared, z);
    EXPECT_LT((z - v).norm(), 1e-8 * v.norm());
    // The contact acts in the full product (which the conjugate gradients use).
    Eigen::Matrix3Xd full;
    colon.body.stiffnessProduct(colon.body.positions(), v, full, true);
    EXPECT_GT((full - declared).norm(), 1e-6 * declared.norm());
}

}  // namespace
}  // namespace colonosim::physics
