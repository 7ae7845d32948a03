// The colon's contact with itself (LumenSelfContact.h): two parts of the
// lumen far apart along the colon push each other apart when they overlap,
// and parts near each other along the colon (a bend) never do.

#include "simcore/physics/LumenSelfContact.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TissueSimulation.h"
#include "tests/physics/ColonRings.h"
#include "tests/physics/SameBits.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace colonosim::physics {
namespace {

constexpr double kRadius = 0.015;      // m
constexpr double kStiffness = 2000.0;  // N/m
constexpr int kPerRing = 6;

/// Two rings of 6 nodes about centres (0, 0, 0) and `other`, both in the
/// x-y plane, `apart` metres apart along the colon.
struct TwoRings {
    Positions x{3, 2 * kPerRing};
    std::vector<LumenSelfContact::Ring> rings;

    TwoRings(const Eigen::Vector3d& other, double apart)
    {
        for (int r = 0; r < 2; ++r) {
            LumenSelfContact::Ring ring;
            ring.arcLength = r * apart;
            ring.radius = kRadius;
            for (int j = 0; j < kPerRing; ++j) {
                const double a = 2.0 * std::numbers::pi * j / kPerRing;
                const int node = r * kPerRing + j;
                x.col(node) = (r == 1 ? other : Eigen::Vector3d::Zero().eval()) +
                              kRadius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
                ring.nodes.push_back(node);
            }
            rings.push_back(ring);
        }
    }
};

/// Rest positions with the two rings 1 m apart: no overlap at rest.
Positions far(const TwoRings& two)
{
    Positions rest = two.x;
    rest.middleCols(kPerRing, kPerRing).colwise() += Eigen::Vector3d(1.0, 0.0, 0.0);
    return rest;
}

Eigen::Vector3d ringSum(const Forces& f, int ring)
{
    return f.middleCols(ring * kPerRing, kPerRing).rowwise().sum();
}

TEST(LumenSelfContact, OverlappingRingsFarApartAlongTheColonArePushedApartByKDelta)
{
    const Eigen::Vector3d other(0.02, 0.005, 0.0);  // 20.6 mm apart: 9.4 mm of overlap
    TwoRings two(other, 0.5);
    const LumenSelfContact term(two.rings, kStiffness, far(two));
    Forces f = Forces::Zero(3, two.x.cols());
    term.addForce(two.x, f);
    const double delta = 2.0 * kRadius - other.norm();
    const double onset = 1e-3;  // the force's smoothed onset, m
    const Eigen::Vector3d expected = -kStiffness * (delta - 0.5 * onset) * other.normalized();  // on ring 0
    EXPECT_NEAR((ringSum(f, 0) - expected).norm(), 0.0, 1e-12);
    EXPECT_NEAR((ringSum(f, 0) + ringSum(f, 1)).norm(), 0.0, 1e-12) << "action and reaction";
    for (int node = 0; node < kPerRing; ++node) {
        EXPECT_NEAR((f.col(node) - expected / kPerRing).norm(), 0.0, 1e-12)
            << "shared equally, node " << node;
    }
    EXPECT_NEAR(term.potentialEnergy(two.x),
                kStiffness * (0.5 * delta * delta - 0.5 * onset * delta + onset * onset / 6.0), 1e-12);
    double deepest = 0.0;
    EXPECT_EQ(term.overlappingPairs(two.x, &deepest), 1);
    EXPECT_NEAR(deepest, delta, 1e-12);
}

TEST(LumenSelfContact, APairThatOverlapsAtRestIsOnlyKeptFromOverlappingFurther)
{
    // A generated colon that coils tightly can overlap itself at rest: the
    // rest shape is stress-free, so only overlap beyond it is resisted.
    TwoRings two(Eigen::Vector3d(0.025, 0.0, 0.0), 0.5);  // 5 mm of overlap at rest
    const LumenSelfContact term(two.rings, kStiffness, two.x);
    Forces f = Forces::Zero(3, two.x.cols());
    term.addForce(two.x, f);
    EXPECT_EQ(f.norm(), 0.0);
    EXPECT_EQ(term.overlappingPairs(two.x), 0);
    two.x.middleCols(kPerRing, kPerRing).colwise() -= Eigen::Vector3d(0.002, 0.0, 0.0);
    term.addForce(two.x, f);
    EXPECT_NEAR(ringSum(f, 1).x(), kStiffness * (0.002 - 0.0005), 1e-9) << "k (delta - s / 2), s = 1 mm";
}

TEST(LumenSelfContact, RingsNearEachOtherAlongTheColonAreNeverPaired)
{
    // 20.6 mm apart in space and 50 mm along the colon: a bend, not a fold
    // (pairs need more than 2 (r_i + r_j) = 60 mm).
    TwoRings two(Eigen::Vector3d(0.02, 0.005, 0.0), 0.05);
    const LumenSelfContact term(two.rings, kStiffness, far(two));
    Forces f = Forces::Zero(3, two.x.cols());
    term.addForce(two.x, f);
    EXPECT_EQ(f.norm(), 0.0);
    EXPECT_EQ(term.overlappingPairs(two.x), 0);
}

TEST(LumenSelfContact, ForceIsTheEnergysGradientAndKIsItsJacobian)
{
    TwoRings two(Eigen::Vector3d(0.018, -0.007, 0.004), 0.5);
    // Deform the rings so that no symmetry hides an error.
    for (int node = 0; node < two.x.cols(); ++node) {
        two.x.col(node) += 1e-3 * Eigen::Vector3d(std::sin(node), std::cos(2.0 * node), std::sin(3.0 * node));
    }
    const LumenSelfContact term(two.rings, kStiffness, far(two));
    Forces f = Forces::Zero(3, two.x.cols());
    term.addForce(two.x, f);
    ASSERT_GT(f.norm(), 1.0);
    const double eps = 1e-7;
    Eigen::Matrix3Xd dx(3, two.x.cols());
    for (int node = 0; node < dx.cols(); ++node) {
        dx.col(node) = Eigen::Vector3d(std::cos(node), std::sin(5.0 * node), std::cos(7.0 * node));
    }
    for (int node = 0; node < two.x.cols(); ++node) {
        for (int k = 0; k < 3; ++k) {
            Positions plus = two.x, minus = two.x;
            plus(k, node) += eps;
            minus(k, node) -= eps;
            const double gradient = (term.potentialEnergy(plus) - term.potentialEnergy(minus)) / (2.0 * eps);
            EXPECT_NEAR(f(k, node), -gradient, 1e-6 * f.cwiseAbs().maxCoeff())
                << "node " << node << " axis " << k;
        }
    }
    Forces fPlus = Forces::Zero(3, two.x.cols()), fMinus = fPlus;
    term.addForce(two.x + eps * dx, fPlus);
    term.addForce(two.x - eps * dx, fMinus);
    const Eigen::Matrix3Xd numeric = (fPlus - fMinus) / (2.0 * eps);
    Eigen::Matrix3Xd product = Eigen::Matrix3Xd::Zero(3, two.x.cols());
    term.addStiffnessProduct(two.x, dx, product);
    EXPECT_LT((product - numeric).cwiseAbs().maxCoeff(), 1e-6 * numeric.cwiseAbs().maxCoeff());

    // K+ drops the positive transverse part: negative semi-definite.
    Eigen::Matrix3Xd definite = Eigen::Matrix3Xd::Zero(3, two.x.cols());
    term.addDefiniteStiffnessProduct(two.x, dx, definite);
    EXPECT_LE((dx.array() * definite.array()).sum(), 0.0);
    EXPECT_GT((product - definite).norm(), 0.0) << "the transverse part is there in K";
}

TEST(LumenSelfContact, StiffnessBoundCoversEveryRowOfK)
{
    TwoRings two(Eigen::Vector3d(0.02, 0.0, 0.0), 0.5);
    const LumenSelfContact term(two.rings, kStiffness, far(two));
    Eigen::VectorXd kRow = Eigen::VectorXd::Zero(two.x.cols()), cRow = kRow;
    term.addStiffnessBound(two.x, kRow, cRow);
    // Row sums of the block norms of K, column by column with unit vectors.
    for (int a = 0; a < two.x.cols(); ++a) {
        double row = 0.0;
        for (int b = 0; b < two.x.cols(); ++b) {
            Eigen::Matrix3d block;
            for (int k = 0; k < 3; ++k) {
                Eigen::Matrix3Xd dx = Eigen::Matrix3Xd::Zero(3, two.x.cols());
                dx(k, b) = 1.0;
                Eigen::Matrix3Xd df = Eigen::Matrix3Xd::Zero(3, two.x.cols());
                term.addStiffnessProduct(two.x, dx, df);
                block.col(k) = df.col(a);
            }
            row += block.operatorNorm();
        }
        EXPECT_GE(kRow[a], row * (1.0 - 1e-12)) << "node " << a;
        EXPECT_GT(row, 0.0);
    }
    EXPECT_EQ(cRow.norm(), 0.0);
}

TEST(LumenSelfContact, APairThatClosesLaterIsFoundWhenTheRingsMove)
{
    // Far apart at first (no candidate pairs), then moved into overlap: the
    // Verlet list is rebuilt once a centre has moved more than half its margin.
    TwoRings two(Eigen::Vector3d(0.2, 0.0, 0.0), 0.5);
    const LumenSelfContact term(two.rings, kStiffness, far(two));
    Forces f = Forces::Zero(3, two.x.cols());
    term.addForce(two.x, f);
    EXPECT_EQ(f.norm(), 0.0);
    two.x.middleCols(kPerRing, kPerRing).colwise() -= Eigen::Vector3d(0.175, 0.0, 0.0);
    term.addForce(two.x, f);
    EXPECT_NEAR(ringSum(f, 1).x(), kStiffness * (2.0 * kRadius - 0.025 - 0.0005), 1e-9);
}

// With an active region, an evaluation at the same positions takes again
// only the centres of rings with an awake node: the forces are those of a
// term that takes every centre, bit for bit, as the awake ring moves, and
// again after the sleeping ring is woken and moves too.
TEST(LumenSelfContact, OnlyRingsWithAnAwakeNodeAreTakenAgainAndTheForcesStayTheSame)
{
    TwoRings two(Eigen::Vector3d(0.025, 0.0, 0.0), 0.5);
    const LumenSelfContact everyCentre(two.rings, kStiffness, far(two));
    LumenSelfContact awakeCentres(two.rings, kStiffness, far(two));
    std::vector<std::uint8_t> awake(2 * kPerRing, 1);
    for (int node = 0; node < kPerRing; ++node) {
        awake[static_cast<size_t>(node)] = 0;  // ring 0 sleeps
    }
    awakeCentres.onActiveSetChanged(awake);
    const auto sameForces = [&] {
        Forces expected = Forces::Zero(3, two.x.cols());
        Forces actual = Forces::Zero(3, two.x.cols());
        everyCentre.addForce(two.x, expected);
        awakeCentres.addForce(two.x, actual);
        EXPECT_GT(expected.norm(), 0.0) << "the rings overlap";
        return testing::differingBits(expected, actual);
    };
    EXPECT_EQ(sameForces(), 0);
    for (int step = 0; step < 5; ++step) {  // ring 1 (awake) pushes further in
        two.x.middleCols(kPerRing, kPerRing).colwise() -= Eigen::Vector3d(0.001, 0.0003, 0.0);
        EXPECT_EQ(sameForces(), 0) << "step " << step;
    }
    awake.assign(awake.size(), 1);  // ring 0 wakes, and moves
    awakeCentres.onActiveSetChanged(awake);
    two.x.leftCols(kPerRing).colwise() += Eigen::Vector3d(0.0, 0.002, 0.001);
    EXPECT_EQ(sameForces(), 0);
}

TEST(LumenSelfContact, TheDefaultColonHasOneBallPerRingAndNoOverlapAtRest)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const ColonBody colon =
        buildColonBody(anatomy, TissueParameters{}, EnvironmentParameters{}, StiffnessCalibration{});
    ASSERT_NE(colon.selfContact, nullptr);
    int perRing = 0;
    while (anatomy.physicsNodes[static_cast<size_t>(perRing)].arcLength ==
           anatomy.physicsNodes[0].arcLength) {
        ++perRing;
    }
    EXPECT_EQ(colon.selfContact->numRings(), (colon.body.numNodes() - 1) / perRing)
        << "every ring, not the apex";
    EXPECT_EQ(colon.selfContact->overlappingPairs(colon.body.positions()), 0);

    TissueParameters off;
    off.selfContactStiffness = 0.0;
    EXPECT_EQ(buildColonBody(anatomy, off, EnvironmentParameters{}, StiffnessCalibration{}).selfContact,
              nullptr);
}

/// Centre distance, m, of the default colon's sigmoid (0.342 m along it)
/// and transverse colon (1.091 m; 44.5 mm apart at rest, their walls 7 mm
/// apart) after 1 s of 2 N pressing each towards the other, spread over
/// its ring; `reach` receives r_i + r_j.
double pressedTogether(double selfContactStiffness, double& reach)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    TissueParameters tissue;
    tissue.selfContactStiffness = selfContactStiffness;
    ColonBody colon = buildColonBody(anatomy, tissue, EnvironmentParameters{}, StiffnessCalibration{});
    solveStaticEquilibrium(colon.body, 1e-5, 1000);
    const LumenSelfContact::Ring a = testing::ringNearest(anatomy, 0.342);
    const LumenSelfContact::Ring b = testing::ringNearest(anatomy, 1.091);
    reach = a.radius + b.radius;
    const auto centre = [&](const LumenSelfContact::Ring& ring) {
        return testing::ringCentre(colon.body.positions(), ring);
    };
    TissueSimulation simulation(colon.body, SteppingPolicy{});
    for (int step = 0; step < 1000; ++step) {
        const Eigen::Vector3d towardsB = (centre(b) - centre(a)).normalized();
        colon.body.clearExternalForces();
        for (const int node : a.nodes) {
            colon.body.applyExternalForce(node, 2.0 / static_cast<double>(a.nodes.size()) * towardsB);
        }
        for (const int node : b.nodes) {
            colon.body.applyExternalForce(node, -2.0 / static_cast<double>(b.nodes.size()) * towardsB);
        }
        simulation.advance();
    }
    return (centre(b) - centre(a)).norm();
}

TEST(LumenSelfContact, TwoPartsOfTheColonPressedTogetherStopWhereTheirLumensMeet)
{
    double reach = 0.0;
    const double with = pressedTogether(TissueParameters{}.selfContactStiffness, reach);
    double reachOff = 0.0;
    const double without = pressedTogether(0.0, reachOff);
    RecordProperty("centre_distance_mm", std::to_string(with * 1e3));
    RecordProperty("without_self_contact_mm", std::to_string(without * 1e3));
    // 2 N on k = 2000 N/m: 1.5 mm of overlap at equilibrium (1 mm and the
    // half of the 1 mm onset); the ring balls follow the tube to about 2 mm.
    EXPECT_GT(with, reach - 3e-3) << "r_i + r_j = " << reach * 1e3 << " mm";
    EXPECT_LT(without, reach - 10e-3) << "without self-contact the two lumens pass into each other";
}

TEST(LumenSelfContact, RefusesARingOfFewerThanThreeNodesByName)
{
    LumenSelfContact::Ring ring{{0, 1}, 0.0, 0.01};
    try {
        const LumenSelfContact term({ring}, kStiffness, Positions::Zero(3, 2));
        FAIL() << "a two-node ring was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("ring 0 has 2 nodes"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace colonosim::physics
