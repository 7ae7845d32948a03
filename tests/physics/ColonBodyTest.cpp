// The colon's tissue body as the builder makes it from the default anatomy,
// its fixations and environment, and the active region.

#include "TubeAnatomy.h"

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/ColonBody.h"
#include "simcore/physics/Gravity.h"
#include "simcore/physics/OrganConstraint.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TissueSimulation.h"
#include "simcore/physics/ViscousDrag.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace colonosim::physics {
namespace {

/// 16 rings of 16 nodes: long enough for a mesenteric part, quick to solve.
TubeResolution shortTube()
{
    TubeResolution tube;
    tube.rings = 16;
    return tube;
}

/// Runs the body at the loop rate for `seconds` (the surrounding drag damps
/// it out within about 0.2 s).
void settle(ColonBody& colon, double seconds)
{
    TissueSimulation simulation(colon.body, SteppingPolicy{});
    for (int s = 0; s < static_cast<int>(seconds / 1e-3); ++s) {
        simulation.advance();
    }
    ASSERT_EQ(simulation.rejectedSteps(), 0);
}

const geometry::ColonAnatomy& defaultAnatomy()
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return anatomy;
}

TEST(ColonBody, DefaultColonHasTheDeclaredMassAndFixations)
{
    const TissueParameters tissue;
    ColonBody colon = buildColonBody(defaultAnatomy(), tissue, EnvironmentParameters{}, {0.5, 0.97});
    const int n = colon.body.numNodes();
    EXPECT_EQ(n, defaultAnatomy().physicsMesh.numVertices());
    // Mass = rho t A; the wall area of a 1.66 m tube of ~20-23 mm radius is
    // about 0.2-0.25 m^2, so 0.2-0.3 kg; the sum of node masses must match
    // rho t times the mesh's own area exactly.
    double area = 0.0;
    const auto& mesh = defaultAnatomy().physicsMesh;
    for (const auto& tri : mesh.triangles) {
        area += 0.5 * (mesh.vertices.col(tri[1]) - mesh.vertices.col(tri[0]))
                          .cross(mesh.vertices.col(tri[2]) - mesh.vertices.col(tri[0]))
                          .norm();
    }
    EXPECT_NEAR(colon.body.masses().sum(), tissue.wallDensity * tissue.wallThickness * area, 1e-9);
    EXPECT_GT(colon.springs->numSprings(), 5 * n);
    int fixed = 0;
    int mesenteric = 0;
    int retroperitoneal = 0;
    for (int i = 0; i < n; ++i) {
        switch (defaultAnatomy().physicsNodes[static_cast<size_t>(i)].attachment) {
        case geometry::Attachment::Fixed: fixed += colon.body.isFixed(i) ? 1 : 0; break;
        case geometry::Attachment::Mesenteric: ++mesenteric; break;
        case geometry::Attachment::Retroperitoneal: ++retroperitoneal; break;
        }
    }
    EXPECT_GT(fixed, 0);
    EXPECT_EQ(colon.mesentery->numTethers(), mesenteric);
    EXPECT_EQ(colon.retroperitoneal->numAnchors(), retroperitoneal);
}

TEST(ColonBody, RefusesParametersOutsideTheirRange)
{
    TissueParameters tissue;
    tissue.wallThickness = 0.02;  // 2 cm
    try {
        (void)buildColonBody(defaultAnatomy(), tissue, EnvironmentParameters{}, {});
        FAIL() << "a 2 cm wall was accepted";
    } catch (const params::ParameterError& error) {
        EXPECT_NE(std::string(error.what()).find("tissue.wallThickness = 0.02 m"), std::string::npos)
            << error.what();
    }
    EnvironmentParameters environment;
    environment.insufflationPressure = -5.0;
    EXPECT_THROW((void)buildColonBody(defaultAnatomy(), TissueParameters{}, environment, {}),
                 params::ParameterError);
}

TEST(ColonBody, GravityPullsTowardsTheTableForEachPatientPosition)
{
    struct Case {
        PatientPosition position;
        Eigen::Vector3d down;
    };
    for (const Case& c : {Case{PatientPosition::Supine, Eigen::Vector3d::UnitY()},
                          Case{PatientPosition::Prone, -Eigen::Vector3d::UnitY()},
                          Case{PatientPosition::LeftLateral, Eigen::Vector3d::UnitX()},
                          Case{PatientPosition::RightLateral, -Eigen::Vector3d::UnitX()}}) {
        EnvironmentParameters environment;
        environment.patientPosition = c.position;
        environment.insufflationPressure = 0.0;
        ColonBody colon = buildColonBody(testing::makeTubeAnatomy(shortTube()), TissueParameters{},
                                         environment, {0.6, 0.95}, {true, true, false, {}});
        const Positions rest = colon.body.positions();
        settle(colon, 0.5);
        const Eigen::Vector3d sag = (colon.body.positions() - rest).rowwise().mean();
        EXPECT_GT(sag.dot(c.down), 0.0) << patientPositionName(c.position);
        EXPECT_GT(sag.dot(c.down), 0.9 * sag.norm())
            << "sag points down for " << patientPositionName(c.position);
    }
    EXPECT_THROW((void)parsePatientPosition("upside_down"), params::ParameterError);
}

TEST(ColonBody, AdhesionsHoldTheirNodes)
{
    // The same 0.5 N pull on a mesenteric node, with and without an adhesion there.
    const geometry::ColonAnatomy anatomy = testing::makeTubeAnatomy(shortTube());
    const int node = 12 * 16 + 4;
    double moved[2] = {0.0, 0.0};
    for (int withAdhesion = 0; withAdhesion < 2; ++withAdhesion) {
        ColonBodyOptions options{false, false, false, {}};
        if (withAdhesion != 0) {
            options.adhesionNodes = {node};
        }
        ColonBody colon =
            buildColonBody(anatomy, TissueParameters{}, EnvironmentParameters{}, {0.6, 0.95}, options);
        const Eigen::Vector3d rest = colon.body.positions().col(node);
        colon.body.applyExternalForce(node, Eigen::Vector3d(0.5, 0.0, 0.0));
        settle(colon, 0.5);
        moved[withAdhesion] = (colon.body.positions().col(node) - rest).norm();
    }
    EXPECT_LT(moved[1], 0.5 * moved[0]) << "free " << moved[0] << " m, adhered " << moved[1] << " m";
    EXPECT_THROW((void)buildColonBody(anatomy, TissueParameters{}, EnvironmentParameters{}, {},
                                      ColonBodyOptions{true, true, true, {99999}}),
                 std::invalid_argument);
}

TEST(OrganConstraint, NoNodeStaysInsideAnOrgan)
{
    geometry::ImplicitShape liver;
    liver.name = "liver";
    liver.centre = Eigen::Vector3d(0.0, 0.0, 0.2);
    liver.semiAxes = Eigen::Vector3d(0.1, 0.06, 0.05);
    geometry::ImplicitShape cavity;
    cavity.name = "cavity";
    cavity.side = geometry::ImplicitShape::Side::KeepInside;
    cavity.centre = Eigen::Vector3d::Zero();
    cavity.semiAxes = Eigen::Vector3d(0.2, 0.15, 0.35);
    const OrganConstraint constraint({liver, cavity});
    Positions x(3, 3);
    x.col(0) = Eigen::Vector3d(0.0, 0.0, 0.19);  // inside the liver
    x.col(1) = Eigen::Vector3d(0.25, 0.0, 0.0);  // outside the cavity
    x.col(2) = Eigen::Vector3d(0.0, 0.1, -0.1);  // allowed
    Velocities v = Velocities::Zero(3, 3);
    v.col(0) = Eigen::Vector3d(0.0, 0.0, 0.3);  // moving into the liver
    const std::vector<int> nodes{0, 1, 2};
    const Eigen::Vector3d untouched = x.col(2);
    EXPECT_EQ(constraint.project(nodes, x, v), 2);
    for (int i = 0; i < 2; ++i) {
        Eigen::Vector3d push;
        EXPECT_LE(liver.penetration(x.col(i), &push), 1e-9);
        EXPECT_LE(cavity.penetration(x.col(i), &push), 1e-9);
    }
    EXPECT_EQ(x.col(2), untouched);
    Eigen::Vector3d gradient;
    (void)liver.signedDistance(x.col(0), &gradient);
    EXPECT_GE(v.col(0).dot(gradient), -1e-12) << "no velocity left into the organ";
}

TEST(ActiveRegion, FarRestingNodesSleepAndALoadWakesThem)
{
    ColonBody colon = buildColonBody(testing::makeTubeAnatomy(shortTube()), TissueParameters{},
                                     EnvironmentParameters{}, {0.6, 0.95});
    ASSERT_TRUE(solveStaticEquilibrium(colon.body, 1e-9).converged);
    TissueSimulation simulation(colon.body, SteppingPolicy{});
    ActiveRegion region(colon.neighbours, SleepParameters{});
    simulation.setActiveRegion(&region);
    for (int s = 0; s < 200; ++s) {
        simulation.advance();
    }
    EXPECT_LT(region.numAwake(), colon.body.numNodes() / 10) << "a settled colon sleeps";
    const int loaded = 12 * 16 + 3;
    colon.body.applyExternalForce(loaded, Eigen::Vector3d(0.2, 0.0, 0.0));
    EXPECT_NE(colon.body.awake()[loaded], 0) << "a force wakes its node at once";
    for (int s = 0; s < 20; ++s) {
        simulation.advance();
    }
    EXPECT_GT(region.numAwake(), 16) << "the disturbance spreads to the neighbourhood";
    EXPECT_THROW(ActiveRegion(colon.neighbours, SleepParameters{-1.0, 1e-3, 0.05, 3}),
                 params::ParameterError);
}

TEST(ActiveRegion, TheSteppingPlanCoversSleepingNodes)
{
    // A sleeping node can wake at any loop step, so the stable-step plan made
    // while (nearly) everything sleeps must still hold for it: the plan of a
    // sleeping colon equals that of the awake one, and a load that wakes a
    // region is integrated without a rejected step.
    ColonBody colon = buildColonBody(testing::makeTubeAnatomy(shortTube()), TissueParameters{},
                                     EnvironmentParameters{}, {0.6, 0.95});
    ASSERT_TRUE(solveStaticEquilibrium(colon.body, 1e-9).converged);
    TissueSimulation simulation(colon.body, SteppingPolicy{});
    const int awakePlan = simulation.substeps();
    ActiveRegion region(colon.neighbours, SleepParameters{});
    simulation.setActiveRegion(&region);
    for (int s = 0; s < 200; ++s) {
        simulation.advance();
    }
    ASSERT_LT(region.numAwake(), colon.body.numNodes() / 10);
    EXPECT_EQ(simulation.substeps(), awakePlan) << simulation.planNote();
    const int loaded = 12 * 16 + 3;
    for (int s = 0; s < 50; ++s) {
        colon.body.clearExternalForces();
        colon.body.applyExternalForce(loaded, Eigen::Vector3d(0.5, 0.0, 0.0));
        simulation.advance();
    }
    EXPECT_EQ(simulation.rejectedSteps(), 0);
    EXPECT_TRUE(colon.body.positions().allFinite());
}

TEST(ActiveRegion, ErrorAgainstTheFullSimulationIsSmall)
{
    // The same settled tube and the same 0.2 N load, with and without sleeping,
    // for 0.3 s: the active region must not change the answer by more than
    // 1% of the loaded node's displacement.
    Positions result[2];
    double displacement = 0.0;
    const int loaded = 12 * 16 + 3;
    for (int sleeping = 0; sleeping < 2; ++sleeping) {
        ColonBody colon = buildColonBody(testing::makeTubeAnatomy(shortTube()), TissueParameters{},
                                         EnvironmentParameters{}, {0.6, 0.95});
        ASSERT_TRUE(solveStaticEquilibrium(colon.body, 1e-9).converged);
        const Eigen::Vector3d rest = colon.body.positions().col(loaded);
        TissueSimulation simulation(colon.body, SteppingPolicy{});
        ActiveRegion region(colon.neighbours, SleepParameters{});
        if (sleeping != 0) {
            simulation.setActiveRegion(&region);
            for (int s = 0; s < 100; ++s) {
                simulation.advance();  // let it fall asleep
            }
        }
        for (int s = 0; s < 300; ++s) {
            colon.body.clearExternalForces();
            colon.body.applyExternalForce(loaded, Eigen::Vector3d(0.2, 0.0, 0.0));
            simulation.advance();
        }
        result[sleeping] = colon.body.positions();
        displacement = (colon.body.positions().col(loaded) - rest).norm();
    }
    const double error = (result[0] - result[1]).colwise().norm().maxCoeff();
    EXPECT_LT(error, 0.01 * displacement)
        << "max error " << error << " m against a displacement of " << displacement;
}

TEST(ActiveRegion, AwakeNodesFeelTheSameForceAndSleepingOnesAreNotSummed)
{
    // The integrators read the force on awake, free nodes only, so the terms
    // sum over those (AwakeEntries.h). With every other node asleep, the force
    // on each awake node equals the all-awake force bit for bit; gravity and
    // the surrounding drag, per-node terms, leave a sleeping node untouched.
    ColonBody colon =
        buildColonBody(defaultAnatomy(), TissueParameters{}, EnvironmentParameters{}, {0.6, 0.95});
    TissueBody& body = colon.body;
    const int n = body.numNodes();
    Velocities v = Velocities::Zero(3, n);
    for (int i = 0; i < n; ++i) {
        v.col(i) = Eigen::Vector3d(std::sin(i), std::cos(2.0 * i), 0.5) * 1e-2;  // m/s, arbitrary
    }
    Forces all;
    body.computeForces(body.positions(), v, all);
    std::vector<std::uint8_t> awake(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        awake[static_cast<size_t>(i)] = i % 2 == 0 ? 1 : 0;
    }
    body.setAwake(awake);
    Forces some;
    body.computeForces(body.positions(), v, some);
    int compared = 0;
    for (const int i : body.integratedNodes()) {
        ASSERT_EQ(i % 2, 0) << "node " << i << " is asleep but integrated";
        ASSERT_EQ(some.col(i), all.col(i)) << "node " << i;
        ++compared;
    }
    EXPECT_GT(compared, n / 3);

    // Per-node terms alone, on a body with no springs: nothing on sleeping nodes.
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(3, 2e-3);
    TissueBody three(Positions::Zero(3, 3), mass);
    three.addForceTerm(std::make_unique<Gravity>(mass, Eigen::Vector3d(0.0, 9.81, 0.0)));
    three.addForceTerm(std::make_unique<ViscousDrag>(mass, 10.0));
    three.setAwake({1, 0, 1});
    Forces f;
    three.computeForces(three.positions(), Velocities::Ones(3, 3), f);
    EXPECT_EQ(f.col(1), Eigen::Vector3d::Zero());
    EXPECT_DOUBLE_EQ(f(1, 0), 2e-3 * 9.81 - 10.0 * 2e-3);
    EXPECT_DOUBLE_EQ(f(1, 2), f(1, 0));
}

}  // namespace
}  // namespace colonosim::physics
