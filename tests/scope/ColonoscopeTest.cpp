// The colonoscope: declared parameters, handle (insertion, rotation), dials
// and the handle load, and refusal of bad device input.

#include "simcore/scope/Colonoscope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace {

using colonosim::params::ParameterError;
using colonosim::scope::Colonoscope;
using colonosim::scope::ScopeParameters;

constexpr double kPi = std::numbers::pi;

Colonoscope insertedScope(double insertion)
{
    Colonoscope scope;
    scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    scope.setInsertion(insertion);
    return scope;
}

TEST(ScopeParameters, DefaultsValidateAndBadValuesNameFieldValueRange)
{
    EXPECT_NO_THROW(ScopeParameters{}.validate());
    ScopeParameters bad;
    bad.flexuralRigidity = std::numeric_limits<double>::quiet_NaN();
    try {
        bad.validate();
        FAIL() << "NaN EI accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("scope.flexuralRigidity"), std::string::npos) << e.what();
    }
    bad = {};
    bad.numNodes = 80.5;
    EXPECT_THROW(bad.validate(), ParameterError);
    bad = {};
    bad.numNodes = 5.0;
    try {
        bad.validate();
        FAIL() << "5 nodes accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("[10, 400]"), std::string::npos) << e.what();
    }
}

// Insertion feeds nodes through the anus at fixed material spacing l = 1.7/79.
TEST(Colonoscope, InsertionFeedsNodesThroughTheAnusAlongTheEntryDirection)
{
    const double l = 1.7 / 79.0;
    struct Case {
        double insertion;
        int nodes;
    };
    for (const Case c : {Case{0.0, 1}, Case{0.5 * l, 1}, Case{1.0 * l, 2}, Case{0.3, 14}, Case{1.7, 80}}) {
        Colonoscope scope = insertedScope(c.insertion);
        scope.step();
        EXPECT_EQ(scope.numInsertedNodes(), c.nodes) << c.insertion;
        // Straight and unloaded: the tip lies at the inserted length along +x.
        EXPECT_NEAR(scope.tipPose().position.x(), c.insertion, 1e-12) << c.insertion;
        EXPECT_NEAR(scope.tipPose().position.y(), 0.0, 1e-12);
    }
}

// Full up-dial bends the tip by the clamped angle (exact: rest rotations
// compose about the same axis); the tip's forward column turns towards up.
TEST(Colonoscope, DialsBendTheTipByTheClampedAngle)
{
    struct Case {
        double upDown;
        double leftRight;
        double expected;  ///< angle between the shaft and the tip's forward direction
    };
    const ScopeParameters p;
    for (const Case c : {Case{0.5, 0.0, 0.5}, Case{-0.5, 0.0, 0.5}, Case{4.0, 0.0, p.maxUpDownAngulation},
                         Case{0.0, 4.0, p.maxLeftRightAngulation}, Case{0.0, -1.0, 1.0}}) {
        Colonoscope scope = insertedScope(1.0);
        scope.setDials(c.upDown, c.leftRight);
        scope.step();
        const Eigen::Matrix3d tip = scope.tipPose().rotation;
        const Eigen::Vector3d forward = tip.col(2);
        // Rotation angle of the tip frame relative to the entry frame (robust near pi).
        const Eigen::Matrix3d entry = (Eigen::Matrix3d() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished();
        const double angle = Eigen::AngleAxisd(entry.transpose() * tip).angle();
        EXPECT_NEAR(angle, c.expected, 1e-9) << c.upDown << ' ' << c.leftRight;
        if (c.upDown > 0.0 && c.expected < 3.0) {
            EXPECT_GT(forward.y(), 0.1);  // up is +y
        }
        if (c.leftRight < 0.0) {
            EXPECT_GT(forward.z(), 0.1);  // the viewer's right, forward x up = +z
        }
        EXPECT_LE(std::abs(scope.upDownDial()), p.maxUpDownAngulation);
    }
}

// Handle rotation with the tip held (a tip torque resisting): the tip turns
// by phi - T L_in / GJ (L_in the inserted length), the twist spread along the shaft; the handle
// torque equals the resisting torque (eq 1 at the clamp).
TEST(Colonoscope, PositiveLeftDialTurnsTheViewToTheViewersLeft)
{
    // The viewer's left is up x forward (x of TipPose); the image's right is
    // forward x up. Operators and devices rely on "left positive".
    Colonoscope straight = insertedScope(0.5);
    straight.step();
    const Eigen::Matrix3d before = straight.tipPose().rotation;
    const Eigen::Vector3d viewersLeft = before.col(1).cross(before.col(2));
    EXPECT_NEAR((viewersLeft - before.col(0)).norm(), 0.0, 1e-12);
    for (const double dial : {0.5, -0.5}) {
        Colonoscope scope = insertedScope(0.5);
        scope.setDials(0.0, dial);
        scope.step();
        const Eigen::Vector3d forward = scope.tipPose().rotation.col(2);
        EXPECT_NEAR(forward.dot(viewersLeft), std::sin(dial), 1e-9) << dial;
        EXPECT_NEAR(forward.dot(before.col(1)), 0.0, 1e-9) << dial;  // no up/down
    }
}

TEST(Colonoscope, HandleRotationReachesTheTipThroughTorsion)
{
    const double insertion = 1.0;
    Colonoscope scope = insertedScope(insertion);
    // Inserted along +x: counter-clockwise seen from the operator, who looks
    // along +x, is a rotation about -x.
    scope.setShaftRotation(0.5);
    const double gj = ScopeParameters{}.torsionalRigidity;
    const double inserted = insertion;  // the whole inserted length is elastic, the stub included
    const double hold = -0.1;           // N m, counter-clockwise seen from the operator (about -x)
    scope.setNodeTorque(scope.numInsertedNodes() - 1, Eigen::Vector3d(-hold, 0.0, 0.0));
    scope.step();
    const Eigen::Matrix3d tip = scope.tipPose().rotation;
    const double tipTwist = -std::atan2(tip(2, 1), tip(1, 1));  // up column turning about -x
    EXPECT_NEAR(tipTwist, 0.5 + hold * inserted / gj, 1e-9);
    EXPECT_NEAR(scope.handleLoad().axialTorque, hold, 1e-12);
}

// The handle load is the sum of the environmental loads (eq 1 at the clamp).
TEST(Colonoscope, HandleLoadSumsTheNodeForces)
{
    Colonoscope scope = insertedScope(0.5);
    scope.setNodeForce(scope.numInsertedNodes() - 1, Eigen::Vector3d(-2.0, 0.0, 0.0));
    scope.setNodeForce(3, Eigen::Vector3d(-1.0, 0.5, 0.0));
    scope.step();
    EXPECT_NEAR(scope.handleLoad().axialForce, -3.0, 1e-12);
    EXPECT_NEAR(scope.handleLoad().force.y(), 0.5, 1e-12);
    scope.clearLoads();
    scope.addGravity(Eigen::Vector3d(0.0, 0.0, -9.81));
    const double weight = 0.2 * 9.81 * 0.5;  // the inserted 0.5 m, stub included
    EXPECT_NEAR(scope.handleLoad().force.z(), -weight, 1e-12);
}

TEST(Colonoscope, BadDeviceInputIsRefusedAtTheBoundary)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Colonoscope scope = insertedScope(0.5);
    for (double bad : {nan, inf, -0.01, 1.71, 1e300}) {
        EXPECT_THROW(scope.setInsertion(bad), ParameterError) << bad;
    }
    for (double bad : {nan, inf, 1e6}) {
        EXPECT_THROW(scope.setShaftRotation(bad), ParameterError) << bad;
        EXPECT_THROW(scope.setDials(bad, 0.0), ParameterError) << bad;
        EXPECT_THROW(scope.setDials(0.0, bad), ParameterError) << bad;
    }
    EXPECT_THROW(
        scope.setHandlePose(Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()),
        ParameterError);
    EXPECT_THROW(
        scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX()),
        ParameterError);
    try {
        scope.setInsertion(2.5);
        FAIL();
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("scope.insertion = 2.5"), std::string::npos) << e.what();
    }
    // The refused inputs left the state as it was.
    EXPECT_EQ(scope.numInsertedNodes(), insertedScope(0.5).numInsertedNodes());
}

}  // namespace

namespace {
// Largest tip displacement between consecutive 0.1 mm insertion increments
// from 2 cm to 30 cm (nodes pass the anus every 2.15 cm), with the dials set
// and a 0.05 N tip load, the chain converged at each increment.
double largestTipJump(double upDown, double tipLoad)
{
    Colonoscope scope = insertedScope(0.02);
    scope.setDials(upDown, 0.0);
    double largest = 0.0;
    Eigen::Vector3d previous = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    for (int k = 0; k <= 2800; ++k) {
        scope.setInsertion(0.02 + 1e-4 * k);
        scope.clearLoads();
        scope.setNodeForce(scope.numInsertedNodes() - 1, Eigen::Vector3d(0.0, -tipLoad, 0.0));
        for (int r = 0; r < 4; ++r) {
            scope.step();
        }
        const Eigen::Vector3d tip = scope.tipPose().position;
        if (k > 0) {
            largest = std::max(largest, (tip - previous).norm());
        }
        previous = tip;
    }
    return largest;
}

// A node passing the anus must not make the tip jump: the bending section's
// entering joint takes its share of the dial angle gradually, and the clamp
// joint's stiffness spans the stub, so the shape is continuous in insertion.
// (Before, one increment of 0.1 mm moved the tip by up to a centimetre.)
TEST(Colonoscope, TheTipMovesContinuouslyAsNodesPassTheAnus)
{
    EXPECT_LT(largestTipJump(1.5, 0.0), 1e-3) << "dials only";
    EXPECT_LT(largestTipJump(0.0, 0.05), 1e-3) << "tip load only";
    EXPECT_LT(largestTipJump(1.5, 0.05), 1e-3) << "both";
}

TEST(Colonoscope, TheClampJointStandsForTheStubAndHalfAnElement)
{
    const double l = 1.7 / 79.0;
    Colonoscope scope = insertedScope(5.25 * l);  // stub 0.25 l
    const Eigen::Vector3d k = scope.rod().stiffness;
    EXPECT_NEAR(scope.rod().jointStiffness(0).x(), k.x() / 0.75, 1e-12 * k.x());
    EXPECT_NEAR(scope.rod().jointStiffness(scope.numInsertedNodes() - 1).x(), 2.0 * k.x(), 1e-12 * k.x());
    EXPECT_NEAR(scope.rod().jointStiffness(2).x(), k.x(), 1e-12 * k.x());
}

// The step guard. One damped step (1 ms, critical damping) of a scope
// inserted 0.6 m along x under a lateral tip load: the tip's motion in the
// step, and the solves the guard refused.
struct GuardedStep {
    double tipMotion = 0.0;  ///< m
    int retries = 0;
    Eigen::Vector3d tip = Eigen::Vector3d::Zero();
};

GuardedStep oneStep(double tipLoad, double maxNodeStep, double dampingRatio = 1.0)
{
    ScopeParameters parameters;
    parameters.maxNodeStep = maxNodeStep;
    Colonoscope scope(parameters);
    scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    scope.setInsertion(0.6);
    const Eigen::Vector3d before = scope.tipPose().position;
    scope.beginStep(1e-3, dampingRatio);
    scope.clearLoads();
    scope.setNodeForce(scope.numInsertedNodes() - 1, Eigen::Vector3d(0.0, -tipLoad, 0.0));
    scope.step();
    return {(scope.tipPose().position - before).norm(), scope.guardRetries(), scope.tipPose().position};
}

/// N on the tip: thrown 187 mm in one step unguarded, 3.5 mm guarded (three refusals).
constexpr double kThrowingLoad = 10.0;

TEST(Colonoscope, TheStepGuardRefusesASolveThatThrowsANodeTooFar)
{
    const double limit = 0.010;  // m: 10 m/s
    const GuardedStep free = oneStep(kThrowingLoad, ScopeParameters::maxNodeStepSpec.maxValue);
    const GuardedStep guarded = oneStep(kThrowingLoad, limit);
    EXPECT_EQ(free.retries, 0);
    EXPECT_GT(free.tipMotion, 3.0 * limit) << "the load must throw the unguarded tip well beyond the limit";
    EXPECT_GT(guarded.retries, 0);
    EXPECT_LE(guarded.tipMotion, limit);
    EXPECT_GT(guarded.tipMotion, 0.1 * limit) << "the guarded step still moves the way the load pushes";
    EXPECT_LT(guarded.tip.y(), 0.0);
}

TEST(Colonoscope, AStepWithinTheGuardsLimitKeepsItsBits)
{
    const GuardedStep free = oneStep(0.1, ScopeParameters::maxNodeStepSpec.maxValue);
    const GuardedStep guarded = oneStep(0.1, 0.010);
    EXPECT_EQ(guarded.retries, 0);
    EXPECT_GT(guarded.tipMotion, 0.0);
    EXPECT_EQ(guarded.tip, free.tip);
}

TEST(Colonoscope, TheDefaultGuardRefusesOnlyASolveThatDiverges)
{
    // The default limit, 0.2 m in a 1 ms step (200 m/s), lets the 10 N throw
    // (187 mm) through bit for bit and refuses a 200 N throw (0.83 m unguarded).
    const double limit = ScopeParameters{}.maxNodeStep;
    const double unguarded = ScopeParameters::maxNodeStepSpec.maxValue;
    const GuardedStep thrown = oneStep(kThrowingLoad, limit);
    const GuardedStep thrownFree = oneStep(kThrowingLoad, unguarded);
    EXPECT_EQ(thrown.retries, 0);
    EXPECT_EQ(thrown.tip, thrownFree.tip);
    EXPECT_LT(thrownFree.tipMotion, limit);
    constexpr double kDivergingLoad = 200.0;  // N on the tip
    const GuardedStep divergedFree = oneStep(kDivergingLoad, unguarded);
    const GuardedStep held = oneStep(kDivergingLoad, limit);
    EXPECT_GT(divergedFree.tipMotion, limit);
    EXPECT_GT(held.retries, 0);
    EXPECT_LE(held.tipMotion, limit);
    RecordProperty("unguarded_throw_mm", std::to_string(divergedFree.tipMotion * 1e3));
    RecordProperty("held_mm", std::to_string(held.tipMotion * 1e3));
}

TEST(Colonoscope, AQuasiStaticStepIsNotGuarded)
{
    // No damping to raise: the rod goes straight to its equilibrium.
    const GuardedStep step = oneStep(kThrowingLoad, 0.010, 0.0);
    EXPECT_EQ(step.retries, 0);
    EXPECT_GT(step.tipMotion, 0.010);
}

}  // namespace
