// The scope's side of contact on the lumen: the Delassus matrix of the
// clamped rod against the chain solver's own response, the one-step Newton
// update, the trust region, release, and the wall's compliance in series.
//
// Each scope node gets a hand-made LumenNodeContact: its own wall cylinder
// along the scope (+x), whose axis lies `height` above the node (+y), so the
// node's depth is height + r - R and its normal is +y (onto the scope, into
// the lumen). A node moved up by dy loses dy of depth, as on a real wall.

#include "simcore/procedure/ContactCoupling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/scope/Colonoscope.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace {

using colonosim::contact::ContactParameters;
using colonosim::contact::LumenContact;
using colonosim::contact::LumenNodeContact;
using colonosim::procedure::ContactCoupling;
using colonosim::procedure::ContactPoints;
using colonosim::scope::Colonoscope;

constexpr double kStiffness = 1e4;    // N/m, the declared contact stiffness
constexpr double kRadius = 0.0065;    // m, scope
constexpr double kWallRadius = 0.02;  // m
constexpr double kLoopStep = 1e-3;    // s
constexpr double kClear = -0.05;      // m: a node 5 cm from its wall

Colonoscope straightScope(double insertion)
{
    Colonoscope scope;
    scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    scope.setInsertion(insertion);
    return scope;
}

/// One contact per point: `depths` gives the pressed points' depths (m),
/// every other point is well clear. The wall point is wall node 0.
std::vector<LumenNodeContact> contactsAt(const std::vector<Eigen::Vector3d>& nodes,
                                         const std::map<int, double>& depths)
{
    std::vector<LumenNodeContact> contacts(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const auto it = depths.find(static_cast<int>(i));
        const double depth = it != depths.end() ? it->second : kClear;
        const double height = kWallRadius - kRadius + depth;
        LumenNodeContact& c = contacts[i];
        c.depth = depth;
        c.normal = Eigen::Vector3d::UnitY();
        c.lever = height;
        c.wallNodes = {0, 0, 0, 0};
        c.weights = {1.0, 0.0, 0.0, 0.0};
        c.wallCentre = nodes[i] + Eigen::Vector3d(0.0, height, 0.0);
        c.wallAxis = Eigen::Vector3d::UnitX();
        c.wallRadius = kWallRadius;
        c.scopeRadius = kRadius;
    }
    return contacts;
}

/// One contact per inserted node.
std::vector<LumenNodeContact> contactsOn(const Colonoscope& scope, const std::map<int, double>& depths)
{
    const auto nodes = scope.nodePositions();
    return contactsAt({nodes.begin(), nodes.end()}, depths);
}

/// One contact per contact point of `points` along the inserted rod.
std::vector<LumenNodeContact> contactsOn(const Colonoscope& scope, const ContactPoints& points,
                                         const std::map<int, double>& depths)
{
    std::vector<Eigen::Vector3d> at;
    for (int p = 0; p < points.count(scope.numInsertedNodes()); ++p) {
        at.push_back(points.at(scope.rod().position, p));
    }
    return contactsAt(at, depths);
}

/// The contact law (its parameters and friction), frictionless here; its
/// tube (the default colon's) is not used by the hand-made contacts.
const LumenContact& law()
{
    static const LumenContact contact = [] {
        ContactParameters parameters;
        parameters.frictionCoefficient = 0.0;
        return LumenContact(
            colonosim::geometry::buildProceduralColon(colonosim::geometry::AnatomyParameters{}), parameters);
    }();
    return contact;
}

/// The same law with the declared Coulomb coefficient.
const LumenContact& frictionLaw()
{
    static const LumenContact contact(
        colonosim::geometry::buildProceduralColon(colonosim::geometry::AnatomyParameters{}),
        ContactParameters{});
    return contact;
}

const Eigen::VectorXd kRigidWall = Eigen::VectorXd::Zero(1);

double solvedDeflection(Colonoscope& scope, int node, const Eigen::Vector3d& force, int measured)
{
    const Eigen::Vector3d before = scope.nodePositions()[static_cast<size_t>(measured)];
    scope.clearLoads();
    scope.setNodeForce(node, force);
    for (int s = 0; s < 40; ++s) {
        scope.step();
    }
    const double moved = (scope.nodePositions()[static_cast<size_t>(measured)] - before).y();
    scope.clearLoads();
    for (int s = 0; s < 40; ++s) {
        scope.step();
    }
    return moved;
}

/// Depths for the five nodes from `first` on, chosen so that every one
/// carries the same load (50 mN) at the solution, d = lambda / k_c +
/// G lambda; `g` receives G, their Delassus matrix.
std::map<int, double> equalLoadDepths(const Colonoscope& scope, int first, Eigen::MatrixXd& g)
{
    std::map<int, double> pressed;
    for (int node = first; node < first + 5; ++node) {
        pressed[node] = 1e-3;  // m
    }
    ContactCoupling probe(kStiffness, 1.0, kLoopStep, 1.0);
    probe.update(contactsOn(scope, pressed), scope.rod(), 0, kRigidWall);
    g = probe.delassus();
    const double load = 0.05;  // N per node
    for (int k = 0; k < static_cast<int>(g.rows()); ++k) {
        pressed[first + k] = load / kStiffness + load * g.row(k).sum();
    }
    return pressed;
}

// G_ab is the rod's compliance: a force along n_b at node b moves node a by
// G_ab along n_a. Checked against the chain solver's converged response for
// small loads (linear range), diagonal and off-diagonal.
TEST(ContactCoupling, DelassusMatrixIsTheRodsOwnCompliance)
{
    Colonoscope scope = straightScope(0.2);
    const int tip = scope.numInsertedNodes() - 1;
    const int mid = tip / 2;
    const auto contacts = contactsOn(scope, {{mid, 1e-6}, {tip, 1e-6}});
    ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0);
    coupling.update(contacts, scope.rod(), 0, kRigidWall);
    ASSERT_EQ(coupling.activeNodes().size(), 2U);
    const Eigen::MatrixXd g = coupling.delassus();
    const double f = 1e-4;  // N
    const double gTipTip = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, f, 0.0), tip) / f;
    const double gMidTip = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, f, 0.0), mid) / f;
    const double gMidMid = solvedDeflection(scope, mid, Eigen::Vector3d(0.0, f, 0.0), mid) / f;
    EXPECT_NEAR(g(1, 1), gTipTip, 1e-3 * gTipTip);
    EXPECT_NEAR(g(0, 1), gMidTip, 1e-3 * gTipTip);
    EXPECT_NEAR(g(0, 0), gMidMid, 1e-3 * gMidMid);
    // Cantilever closed form for the tip: L^3 / 3 EI (discrete rod, 1%).
    const double ei = colonosim::scope::ScopeParameters{}.flexuralRigidity;
    EXPECT_NEAR(g(1, 1), std::pow(0.2, 3) / (3.0 * ei), 0.01 * g(1, 1));
}

// For one contact the solve is the Newton step: lambda = k_c d0 / (1 + k_c G)
// (the depth re-measured on the wall at the predicted position loses G lambda),
// and the rod under lambda rises by G lambda.
TEST(ContactCoupling, OneContactIsResolvedInOneStep)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    const double depth = 2e-3;  // m
    const auto contacts = contactsOn(scope, {{tip, depth}});
    ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0);
    coupling.update(contacts, scope.rod(), 0, kRigidWall);
    ASSERT_EQ(coupling.activeNodes().size(), 1U);
    coupling.solveAndApply(scope.rod(), law());
    const double g = coupling.delassus()(0, 0);
    const double lambda = coupling.loads().col(tip).y();
    EXPECT_NEAR(lambda, kStiffness * depth / (1.0 + kStiffness * g), 1e-3 * lambda);
    for (int i = 0; i < tip; ++i) {
        EXPECT_EQ(coupling.loads().col(i).norm(), 0.0) << "node " << i;
    }
    const double rise = solvedDeflection(scope, tip, Eigen::Vector3d(0.0, lambda, 0.0), tip);
    EXPECT_NEAR(rise, g * lambda, 1e-3 * rise);
    EXPECT_GT(rise, 0.99 * depth) << "a 15 cm tip is far softer than the penalty: it gives way";
}

// With relaxation omega each solve applies the fraction omega of its load
// change: the first solve of a contact carries omega of the Newton load, and
// each re-solve on the shape the rod took under it moves omega of the rest
// of the way.
TEST(ContactCoupling, EachSolveAppliesTheRelaxedFractionOfItsLoadChange)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    const double depth = 2e-3;  // m
    const auto contacts = contactsOn(scope, {{tip, depth}});
    ContactCoupling full(kStiffness, 1.0, kLoopStep, 1.0);
    full.update(contacts, scope.rod(), 0, kRigidWall);
    full.solveAndApply(scope.rod(), law());
    const double newton = full.loads().col(tip).y();
    ASSERT_GT(newton, 0.0);

    const double omega = 0.3;
    Colonoscope relaxedScope = straightScope(0.15);
    const double start = relaxedScope.nodePositions()[static_cast<size_t>(tip)].y();
    ContactCoupling relaxed(kStiffness, 1.0, kLoopStep, omega);
    double expected = 0.0;
    for (int solve = 1; solve <= 4; ++solve) {
        // Re-measured on the shape the last load gave: the tip has risen.
        const double risen = relaxedScope.nodePositions()[static_cast<size_t>(tip)].y() - start;
        relaxedScope.clearLoads();
        // The coupling reads the contacts again in solveAndApply(): they must outlive it.
        const auto remeasured = contactsOn(relaxedScope, {{tip, depth - risen}});
        relaxed.update(remeasured, relaxedScope.rod(), 0, kRigidWall);
        relaxed.solveAndApply(relaxedScope.rod(), law());
        expected += omega * (newton - expected);
        EXPECT_NEAR(relaxed.loads().col(tip).y(), expected, 2e-3 * newton) << "solve " << solve;
        EXPECT_EQ(relaxed.normalLoads()[static_cast<size_t>(tip)].y(), relaxed.loads().col(tip).y());
        for (int s = 0; s < 40; ++s) {
            relaxedScope.step();  // the chain's equilibrium under the applied load
        }
    }
}

// A contact-driven step never moves a node by more than the trust region.
TEST(ContactCoupling, TheTrustRegionBoundsTheMotionOfOneStep)
{
    Colonoscope scope = straightScope(0.3);
    const int tip = scope.numInsertedNodes() - 1;
    const auto contacts = contactsOn(scope, {{tip, 0.02}});
    const double maxStep = 1e-4;  // m
    ContactCoupling coupling(kStiffness, maxStep, kLoopStep, 1.0);
    coupling.update(contacts, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), law());
    const double g = coupling.delassus()(0, 0);
    const double lambda = coupling.loads().col(tip).y();
    EXPECT_GT(lambda, 0.0);
    // The whole predicted motion |C n| lambda is held to maxStep; its normal
    // part G lambda is at most that, and on a straight cantilever nearly all of it.
    EXPECT_LE(g * lambda, maxStep * (1.0 + 1e-9));
    EXPECT_GT(g * lambda, 0.99 * maxStep);
}

// A node that came into its wall over the last step (the shaft behind it
// springing forward, not the insertion) may be pushed back by the distance
// its depth grew as well as by the trust region: otherwise a tip driven on by
// the chain at metres per second outruns a load that grows by maxStep / reach
// a step and passes through the wall. Re-measures within one step keep the
// step's allowance; letting go stays bounded by the trust region alone.
TEST(ContactCoupling, ANodeComingIntoItsWallIsPushedBackByTheWayItCameIn)
{
    Colonoscope scope = straightScope(0.3);
    const int tip = scope.numInsertedNodes() - 1;
    const double maxStep = 1e-4;  // m
    const double came = 2e-3;     // m the tip's depth grows by over one step
    ContactCoupling coupling(kStiffness, maxStep, kLoopStep, 1.0);
    // (The coupling reads its contacts again in solveAndApply(): each set outlives its solve.)
    const auto pressed = contactsOn(scope, {{tip, 0.02}});
    coupling.update(pressed, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), law());
    const double g = coupling.delassus()(0, 0);
    const double first = coupling.loads().col(tip).y();
    EXPECT_LE(g * first, maxStep * (1.0 + 1e-9));  // no history: the trust region alone

    // The next step starts with the tip 2 mm deeper (the chain's own motion).
    const auto deeper = contactsOn(scope, {{tip, 0.02 + came}});
    coupling.update(deeper, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), law());
    const double raised = coupling.loads().col(tip).y() - first;
    EXPECT_LE(g * raised, (maxStep + came) * (1.0 + 1e-9));
    EXPECT_GT(g * raised, 0.99 * (maxStep + came));
    // A re-measure within the same step keeps the step's allowance.
    const double before = coupling.loads().col(tip).y();
    coupling.update(deeper, scope.rod(), 0, kRigidWall, false);
    coupling.solveAndApply(scope.rod(), law());
    EXPECT_GT(g * (coupling.loads().col(tip).y() - before), 0.99 * (maxStep + came));

    // The wall falls away: the load lets go by at most maxStep / reach
    // (maxStep over the whole motion |C n| >= G: a little less than maxStep / G).
    const double held = coupling.loads().col(tip).y();
    const auto away = contactsOn(scope, {{tip, -0.01}});
    coupling.update(away, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), law());
    const double released = held - coupling.loads().col(tip).y();
    EXPECT_LE(released, maxStep / g * (1.0 + 1e-9));
    EXPECT_GT(released, 0.99 * maxStep / g);
}

// A node that carried a load and is now clear of its wall lets go at once;
// no load pulls.
TEST(ContactCoupling, ReleaseIsImmediateAndContactNeverPulls)
{
    Colonoscope scope = straightScope(0.15);
    const int tip = scope.numInsertedNodes() - 1;
    const auto pressed = contactsOn(scope, {{tip, 1e-3}});
    ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0);
    coupling.update(pressed, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), law());
    ASSERT_GT(coupling.loads().col(tip).y(), 0.0);
    // The wall moves 5 mm away: the node still carries its load into the
    // update (it is active), and the solve releases it.
    const auto clear = contactsOn(scope, {{tip, -0.005}});
    coupling.update(clear, scope.rod(), 0, kRigidWall);
    EXPECT_EQ(coupling.activeNodes().size(), 1U);
    coupling.solveAndApply(scope.rod(), law());
    EXPECT_EQ(coupling.loads().col(tip).norm(), 0.0);
    for (int i = 0; i < scope.numInsertedNodes(); ++i) {
        EXPECT_GE(coupling.loads().col(i).y(), 0.0) << "node " << i;
    }
}

// The wall's compliance (dt^2 / m of its node, weighted) adds to the rod's
// in series: G grows by exactly that, and the same depth gives less load.
TEST(ContactCoupling, TheWallsComplianceAddsInSeries)
{
    Colonoscope scope = straightScope(0.08);
    const int tip = scope.numInsertedNodes() - 1;
    const auto contacts = contactsOn(scope, {{tip, 1e-3}});
    ContactCoupling rigid(kStiffness, 1.0, kLoopStep, 1.0);
    rigid.update(contacts, scope.rod(), 0, kRigidWall);
    const Eigen::VectorXd soft = Eigen::VectorXd::Constant(1, 2e-3);  // m/N: a 0.5 g node at 1 ms
    ContactCoupling compliant(kStiffness, 1.0, kLoopStep, 1.0);
    compliant.update(contacts, scope.rod(), 0, soft);
    EXPECT_NEAR(compliant.delassus()(0, 0) - rigid.delassus()(0, 0), 2e-3, 1e-12);
    rigid.solveAndApply(scope.rod(), law());
    compliant.solveAndApply(scope.rod(), law());
    EXPECT_LT(compliant.loads().col(tip).y(), rigid.loads().col(tip).y());
    EXPECT_GT(compliant.loads().col(tip).y(), 0.0);
}

// Friction reaches the scope, not only the wall: a pressed node sliding
// along the wall carries mu lambda against its slip in the rod's loads (the
// regularised Coulomb law, its stick below max(v_s, 2 mu lambda G / dt)),
// the same load the wall carries the opposite of.
TEST(ContactCoupling, FrictionActsOnTheScopeAsOnTheWall)
{
    const int tip = straightScope(0.15).numInsertedNodes() - 1;
    const double mu = ContactParameters{}.frictionCoefficient;
    // The normal load does not depend on the slip: find it and G first.
    Colonoscope probe = straightScope(0.15);
    const auto pressed = contactsOn(probe, {{tip, 1e-3}});
    ContactCoupling first(kStiffness, 1.0, kLoopStep, 1.0);
    first.update(pressed, probe.rod(), 0, kRigidWall);
    const double g = first.delassus()(0, 0);
    first.solveAndApply(probe.rod(), frictionLaw());
    const double lambda = first.normalLoads()[static_cast<size_t>(tip)].norm();
    ASSERT_GT(lambda, 0.0);
    const double stick = std::max(ContactParameters{}.stickVelocity, 2.0 * mu * lambda * g / kLoopStep);
    // Sliding fast (4 stick speeds): Coulomb, mu lambda; slowly (a quarter): viscous.
    for (const double speed : {4.0 * stick, 0.25 * stick}) {
        Colonoscope scope = straightScope(0.15);
        auto contacts = contactsOn(scope, {{tip, 1e-3}});
        contacts[static_cast<size_t>(tip)].slip = Eigen::Vector3d(speed, 0.0, 0.0);  // m/s, along the scope
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        const Eigen::Vector3d before = scope.rod().force[static_cast<size_t>(tip)];
        coupling.solveAndApply(scope.rod(), frictionLaw());
        const Eigen::Vector3d applied = scope.rod().force[static_cast<size_t>(tip)] - before;
        EXPECT_NEAR(applied.y(), lambda, 1e-12);
        EXPECT_NEAR(applied.x(), -mu * lambda * std::min(1.0, speed / stick), 1e-12) << "slip " << speed;
        EXPECT_NEAR((applied - coupling.loads().col(tip)).norm(), 0.0, 1e-15);
    }
    // Without slip there is no friction.
    EXPECT_EQ(probe.rod().force[static_cast<size_t>(tip)].x(), 0.0);
}

// Friction is explicit (it opposes the slip of the last step), so its stick
// must be soft enough that the friction of all the contacts together does
// not throw the scope back past where it slid from. Five pressed nodes near
// the tip of a 30 cm shaft, all slipping sideways at a creeping speed: the
// friction they get moves no node back as far as it slid in one step. With
// each node's stick set from its own compliance alone (the friction of the
// other four left out) it would be thrown back by more than twice its slip;
// a shaft in the sigmoid swung from wall to wall so.
TEST(ContactCoupling, TheFrictionOfManyContactsTogetherCannotReverseTheirSlip)
{
    Colonoscope scope = straightScope(0.3);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::MatrixXd g;
    const std::map<int, double> pressed = equalLoadDepths(scope, tip - 4, g);
    ASSERT_EQ(g.rows(), 5);
    auto contacts = contactsOn(scope, pressed);
    const double slip = 1e-4;  // m/s sideways (+z): well inside every node's stick
    for (const auto& [node, depth] : pressed) {
        contacts[static_cast<size_t>(node)].slip = Eigen::Vector3d(0.0, 0.0, slip);
    }
    ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0);
    coupling.update(contacts, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), frictionLaw());
    const std::vector<Eigen::Vector3d> before(scope.nodePositions().begin(), scope.nodePositions().end());
    double pushedBack = 0.0;
    for (const auto& [node, depth] : pressed) {
        ASSERT_GT(coupling.normalLoads()[static_cast<size_t>(node)].y(), 0.0) << "node " << node;
        ASSERT_LT(coupling.loads().col(node).z(), 0.0) << "node " << node << ": friction opposes the slip";
    }
    for (int s = 0; s < 40; ++s) {
        scope.step();  // the chain's equilibrium under the applied loads
    }
    for (const auto& [node, depth] : pressed) {
        const auto i = static_cast<size_t>(node);
        pushedBack = std::max(pushedBack, -(scope.nodePositions()[i] - before[i]).z());
    }
    EXPECT_GT(pushedBack, 0.0);
    EXPECT_LT(pushedBack, slip * kLoopStep) << "the friction threw a node back past where it slid from";
    // The same friction with each node's stick from its own compliance
    // (2 mu lambda G_bb / dt) would move node a back by
    // v dt sum_b G_ab / (2 G_bb) (sideways compliance = G on a straight
    // rod): more than the slip, so this arrangement tells the two apart.
    double ownStick = 0.0;
    for (Eigen::Index a = 0; a < g.rows(); ++a) {
        double back = 0.0;
        for (Eigen::Index b = 0; b < g.cols(); ++b) {
            back += g(a, b) / (2.0 * g(b, b));
        }
        ownStick = std::max(ownStick, back);
    }
    EXPECT_GT(ownStick, 1.0);
}

/// A tip pressed into a fixed wall (+y) and slipping at a set speed, step
/// after step: each step the coupling solves on the tip's depth measured from
/// how far it has risen, and the chain settles under the loads (so that the
/// shape carries them, as in the loop).
struct PressedTip {
    explicit PressedTip(bool sticking) : coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, {}, false, sticking) {}

    /// One loop step; `touching` false: the wall has moved 5 mm away.
    void step(const Eigen::Vector3d& slip, bool touching = true)
    {
        const double rise = scope.nodePositions()[static_cast<size_t>(tip)].y() - start;
        std::map<int, double> depths;
        depths[tip] = touching ? kDepth - rise : -5e-3;
        auto contacts = contactsOn(scope, depths);
        contacts[static_cast<size_t>(tip)].slip = slip;
        scope.clearLoads();
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), frictionLaw());
        for (int s = 0; s < 40; ++s) {
            scope.step();
        }
    }
    [[nodiscard]] Eigen::Vector3d friction() const
    {
        return coupling.loads().col(tip) - coupling.normalLoads()[static_cast<size_t>(tip)];
    }
    [[nodiscard]] double normal() const { return coupling.normalLoads()[static_cast<size_t>(tip)].y(); }

    static constexpr double kDepth = 1e-3;  // m
    Colonoscope scope = straightScope(0.15);
    int tip = scope.numInsertedNodes() - 1;
    double start = scope.nodePositions()[static_cast<size_t>(tip)].y();
    ContactCoupling coupling;
};

// Sticking friction (contact.stickingFriction): a pressed tip slipping along
// the scope at a steady creep, step after step, carries a friction that grows
// by the same load each step (the load that stops one step's slip,
// slip dt / (2 R)) until it reaches mu lambda, and stays there (Coulomb).
// Found afresh each step (the default) it stays at one step's load, a small
// fraction of mu lambda set by the slip speed alone.
TEST(ContactCoupling, StickingFrictionGrowsStepByStepToTheCoulombLimit)
{
    const double mu = ContactParameters{}.frictionCoefficient;
    const Eigen::Vector3d slip(5e-3, 0.0, 0.0);  // m/s
    PressedTip fresh(false);
    PressedTip sticking(true);
    std::vector<double> grown;
    std::vector<double> found;
    std::vector<double> limit;  // mu lambda of each step, N
    for (int s = 0; s < 60; ++s) {
        fresh.step(slip);
        sticking.step(slip);
        found.push_back(fresh.friction().x());
        grown.push_back(sticking.friction().x());
        limit.push_back(mu * sticking.normal());
        ASSERT_GT(limit.back(), 0.0);
        EXPECT_NEAR(sticking.friction().norm(), -grown.back(), 1e-15) << "step " << s << ": against the slip";
    }
    const double increment = grown[2] - grown[1];
    ASSERT_LT(increment, 0.0) << "friction opposes the slip";
    ASSERT_LT(-grown[1], 0.2 * limit[1]) << "one step's load is well inside the cone";
    for (size_t s = 2; s < found.size(); ++s) {
        EXPECT_NEAR(found[s], found[1], 1e-9 * std::abs(found[1])) << "found afresh, it does not grow";
    }
    EXPECT_NEAR(found[1], grown[0], 0.01 * std::abs(found[1])) << "the first step is the same either way";
    bool reached = false;
    for (size_t s = 2; s < grown.size(); ++s) {
        EXPECT_GE(grown[s], -limit[s] * (1.0 + 1e-12)) << "step " << s << ": beyond the friction cone";
        if (grown[s - 1] + increment > -limit[s]) {
            EXPECT_NEAR(grown[s] - grown[s - 1], increment, 1e-6 * std::abs(increment)) << "step " << s;
        } else {
            EXPECT_NEAR(grown[s], -limit[s], 1e-12 * limit[s]) << "step " << s << ": Coulomb";
            reached = true;
        }
    }
    EXPECT_TRUE(reached) << "60 steps of slip reach the Coulomb limit";
}

// A stuck point holds its friction while it does not slip (static friction,
// where the friction found afresh is zero), and lets go of it when it leaves
// its wall: pressed again, it starts from none.
TEST(ContactCoupling, StickingFrictionHoldsWithoutSlipAndLetsGoOffTheWall)
{
    const Eigen::Vector3d slip(5e-3, 0.0, 0.0);  // m/s
    const Eigen::Vector3d none = Eigen::Vector3d::Zero();
    PressedTip tip(true);
    PressedTip fresh(false);
    for (int s = 0; s < 3; ++s) {
        tip.step(slip);
        fresh.step(slip);
    }
    const double held = tip.friction().x();
    ASSERT_LT(held, 0.0);
    for (int s = 0; s < 5; ++s) {
        tip.step(none);
        fresh.step(none);
        EXPECT_NEAR(tip.friction().x(), held, 1e-12 * std::abs(held)) << "step " << s << " without slip";
        EXPECT_EQ(fresh.friction().norm(), 0.0) << "found afresh, no slip gives no friction";
    }
    tip.step(slip, false);
    EXPECT_EQ(tip.friction().norm(), 0.0) << "off the wall";
    EXPECT_EQ(tip.normal(), 0.0);
    for (int s = 0; s < 5; ++s) {
        tip.step(none);  // the tip settles back onto the wall
    }
    ASSERT_GT(tip.normal(), 0.0);
    EXPECT_EQ(tip.friction().norm(), 0.0) << "pressed again without slip";
}

namespace {

/// Five contacts on every second node of a straight shaft, deeper towards the
/// tip (15, 10, 6, 3 and 1 mm): each node's load moves the others.
std::vector<LumenNodeContact> fiveCoupledContacts(const Colonoscope& scope)
{
    const int tip = scope.numInsertedNodes() - 1;
    std::map<int, double> depths;
    const std::array<double, 5> depth{15e-3, 10e-3, 6e-3, 3e-3, 1e-3};  // m, tip first
    for (int k = 0; k < 5; ++k) {
        depths[tip - 2 * k] = depth[static_cast<size_t>(k)];
    }
    return contactsOn(scope, depths);
}

/// Six contacts on every third node from the tip, 1-6 mm deep, with walls on
/// alternate sides turned a quarter round the shaft each time: the shaft is
/// pressed between them, and every contact keeps a load.
std::vector<LumenNodeContact> sixPressedContacts(const Colonoscope& scope)
{
    const int tip = scope.numInsertedNodes() - 1;
    std::map<int, double> depths;
    const std::array<double, 6> depth{4e-3, 3e-3, 6e-3, 2e-3, 5e-3, 1e-3};  // m, tip first
    for (int k = 0; k < 6; ++k) {
        depths[tip - 3 * k] = depth[static_cast<size_t>(k)];
    }
    auto contacts = contactsOn(scope, depths);
    for (int k = 0; k < 6; ++k) {
        LumenNodeContact& c = contacts[static_cast<size_t>(tip - 3 * k)];
        const double angle = 1.5707963267948966 * k + (k % 2 == 1 ? 3.141592653589793 : 0.0);
        const Eigen::Vector3d side(0.0, std::cos(angle), std::sin(angle));
        c.normal = side;
        c.wallCentre = scope.nodePositions()[static_cast<size_t>(tip - 3 * k)] + c.lever * side;
    }
    return contacts;
}

}  // namespace

// The sweeps stop at contact.couplingSweeps, or earlier once no load changes
// by more than contact.sweepTolerance in a sweep; residual() is that largest
// change of the last sweep. Five contacts along one shaft, deeper towards the
// tip, couple through the shaft's compliance (each node's load moves the
// others): their loads change over eight sweeps before they settle, to the
// last bit.
TEST(ContactCoupling, TheSweepsStopAtTheirCapOrOnceTheLoadsSettle)
{
    const auto solved = [](colonosim::procedure::SweepLimits limits) {
        Colonoscope scope = straightScope(0.3);
        const auto contacts = fiveCoupledContacts(scope);
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, limits);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), law());
        return std::pair{coupling.sweeps(), coupling.residual()};
    };
    const auto [capped, left] = solved({2, 1e-12});
    EXPECT_EQ(capped, 2);
    EXPECT_GT(left, 1e-3) << "two sweeps leave the coupled loads changing";
    const auto [settled, settledLeft] = solved({500, 1e-6});
    EXPECT_GT(settled, 2);
    EXPECT_LT(settled, 500);
    EXPECT_LT(settledLeft, 1e-6);
    const auto [looser, looserLeft] = solved({500, 0.02});
    EXPECT_LT(looser, settled) << "a looser tolerance stops sooner";
    EXPECT_LT(looserLeft, 0.02);
    EXPECT_GE(looserLeft, 1e-6);
}

// A solve that another solve of the step follows (solveAndApply()'s
// lastSolve false) sweeps to SweepLimits::passTolerance; the last one to
// SweepLimits::tolerance. The five coupled contacts above.
TEST(ContactCoupling, ASolveThatAnotherFollowsSweepsToThePassTolerance)
{
    const auto solved = [](bool lastSolve) {
        Colonoscope scope = straightScope(0.3);
        const auto contacts = fiveCoupledContacts(scope);
        colonosim::procedure::SweepLimits limits{500, 1e-6};
        limits.passTolerance = 0.02;
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, limits);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), law(), lastSolve);
        return std::pair{coupling.sweeps(), coupling.residual()};
    };
    const auto [last, lastLeft] = solved(true);
    const auto [pass, passLeft] = solved(false);
    EXPECT_LT(lastLeft, 1e-6);
    EXPECT_LT(passLeft, 0.02);
    EXPECT_GE(passLeft, 1e-6) << "the pass stopped before the full tolerance";
    EXPECT_LT(pass, last) << "and sooner";
}

// Anderson acceleration (SweepLimits::acceleration) changes the way to the
// loads, not where they settle: on the five coupled contacts above, swept to
// 1e-9 N, the accelerated sweeps stop on the same loads within 1e-7 N, with
// the stop judged on a plain sweep's change as without it. (There the plain
// sweeps settle in 8; depth 2 takes 6, and 3 or more, capped at the four
// differences that five loads allow, 9.)
TEST(ContactCoupling, AcceleratedSweepsSettleOnTheSameLoads)
{
    const auto solved = [](int acceleration) {
        Colonoscope scope = straightScope(0.3);
        const auto contacts = fiveCoupledContacts(scope);
        colonosim::procedure::SweepLimits limits{500, 1e-9};
        limits.acceleration = acceleration;
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, limits);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), law());
        return std::tuple{coupling.sweeps(), coupling.residual(), coupling.normalLoads()};
    };
    const auto [plainSweeps, plainLeft, plain] = solved(0);
    EXPECT_LT(plainLeft, 1e-9);
    for (const int depth : {2, 5, 10}) {
        const auto [sweeps, left, loads] = solved(depth);
        RecordProperty("sweeps_at_depth_" + std::to_string(depth),
                       std::to_string(sweeps) + " against " + std::to_string(plainSweeps));
        EXPECT_LT(left, 1e-9) << "depth " << depth;
        EXPECT_LT(sweeps, 500) << "depth " << depth;
        ASSERT_EQ(loads.size(), plain.size());
        double largest = 0.0;
        for (size_t i = 0; i < plain.size(); ++i) {
            largest = std::max(largest, plain[i].norm());
            EXPECT_NEAR((loads[i] - plain[i]).norm(), 0.0, 1e-7) << "node " << i << ", depth " << depth;
        }
        EXPECT_GT(largest, 0.01) << "the contacts carry loads";
    }
}

// The prefix sweeps sum the same predicted motions as the dense ones through
// the rod's prefix sums: sweep by sweep the loads agree to rounding (1e-15 N
// on loads of 0.02-1.8 N), with and without the wall's shared compliance,
// for six contacts on a shaft bent by the dials (its nodes off the axis).
TEST(ContactCoupling, PrefixSweepsFollowTheDenseSweepsToRounding)
{
    for (const bool sharedWall : {false, true}) {
        for (const int sweeps : {1, 3, 30}) {
            const auto solved = [&](bool prefix) {
                Colonoscope scope = straightScope(0.4);
                scope.setDials(1.2, -0.7);
                for (int s = 0; s < 60; ++s) {
                    scope.step();
                }
                const auto contacts = sixPressedContacts(scope);
                ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {sweeps, 1e-12, prefix});
                const Eigen::VectorXd wall = sharedWall ? Eigen::VectorXd::Constant(1, 2e-4) : kRigidWall;
                coupling.update(contacts, scope.rod(), 0, wall);
                coupling.solveAndApply(scope.rod(), law());
                return coupling.normalLoads();
            };
            const auto dense = solved(false);
            const auto summed = solved(true);
            ASSERT_EQ(dense.size(), summed.size());
            double largest = 0.0;
            int loaded = 0;
            for (size_t i = 0; i < dense.size(); ++i) {
                largest = std::max(largest, dense[i].norm());
                loaded += dense[i].norm() > 0.0 ? 1 : 0;
                EXPECT_NEAR((summed[i] - dense[i]).norm(), 0.0, 1e-9)
                    << "node " << i << ", " << sweeps << " sweeps, shared wall " << sharedWall;
            }
            EXPECT_GT(largest, 0.1) << "the contacts carry loads";
            EXPECT_EQ(loaded, 6) << "every contact keeps a load";
        }
    }
}

}  // namespace

// A point inside an element (contact.elementPoints) is as compliant as the
// rod at that place: a force there, shared by the element's two nodes in
// proportion to where it lies, moves it by G along the normal, as the chain
// solver finds; and the load the coupling settles on reaches the rod as
// those two shares.
TEST(ContactCoupling, APointInsideAnElementIsAsCompliantAsTheRodThere)
{
    Colonoscope scope = straightScope(0.2);
    const int tip = scope.numInsertedNodes() - 1;
    for (const int inner : {1, 3}) {
        const ContactPoints points{inner + 1};
        // The last element's first inner point, a quarter or half of the way.
        const int point = points.count(tip + 1) - 1 - inner;
        ASSERT_EQ(points.node(point), tip - 1);
        const double t = points.share(point);
        EXPECT_DOUBLE_EQ(t, 1.0 / (inner + 1));
        const double depth = 1e-3;  // m
        const auto contacts = contactsOn(scope, points, {{point, depth}});
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, points);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        ASSERT_EQ(coupling.activeNodes().size(), 1U);
        const double g = coupling.delassus()(0, 0);

        const double f = 1e-4;  // N
        const auto at = [&] { return points.at(scope.rod().position, point); };
        const Eigen::Vector3d before = at();
        scope.clearLoads();
        scope.setNodeForce(tip - 1, Eigen::Vector3d(0.0, (1.0 - t) * f, 0.0));
        scope.setNodeForce(tip, Eigen::Vector3d(0.0, t * f, 0.0));
        for (int s = 0; s < 40; ++s) {
            scope.step();
        }
        const double moved = (at() - before).y();
        scope.clearLoads();
        for (int s = 0; s < 40; ++s) {
            scope.step();
        }
        EXPECT_NEAR(g, moved / f, 1e-3 * g) << inner << " inner points";
        // Between the nodes' own compliances: the point lies between them.
        const auto nodeContacts = contactsOn(scope, {{tip - 1, 1e-6}, {tip, 1e-6}});
        ContactCoupling nodes(kStiffness, 1.0, kLoopStep, 1.0);
        nodes.update(nodeContacts, scope.rod(), 0, kRigidWall);
        const Eigen::MatrixXd gn = nodes.delassus();
        EXPECT_GT(g, gn(0, 0));
        EXPECT_LT(g, gn(1, 1));

        scope.clearLoads();
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), law());
        const double lambda = coupling.loads().col(point).y();
        EXPECT_NEAR(lambda, kStiffness * depth / (1.0 + kStiffness * g), 1e-3 * lambda);
        ASSERT_EQ(coupling.loads().cols(), points.count(tip + 1));
        EXPECT_DOUBLE_EQ(scope.rod().force[static_cast<size_t>(tip - 1)].y(), (1.0 - t) * lambda);
        EXPECT_DOUBLE_EQ(scope.rod().force[static_cast<size_t>(tip)].y(), t * lambda);
        for (int i = 0; i < tip - 1; ++i) {
            EXPECT_EQ(scope.rod().force[static_cast<size_t>(i)].norm(), 0.0) << "node " << i;
        }
        scope.clearLoads();
    }
}

// Side normals (contact.sideNormals): the wall pushes the shaft across its
// axis. A node's wall cylinder tilted by theta against the shaft (+x) has the
// normal (-sin theta, cos theta, 0): the load keeps only its part across the
// shaft, the depth is still measured along the normal, so the Newton step
// uses n^T C d, and the tip, which meets the wall head on, keeps the wall's
// normal, as does a node whose wall is met nearly head on (less than 0.2 of
// its normal across the shaft).
TEST(ContactCoupling, SideNormalsPushAcrossTheShaft)
{
    const auto tilted = [](std::vector<LumenNodeContact>& contacts, const Colonoscope& scope, int node,
                           double theta) {
        LumenNodeContact& c = contacts[static_cast<size_t>(node)];
        const Eigen::Vector3d normal(-std::sin(theta), std::cos(theta), 0.0);
        c.normal = normal;
        c.wallAxis = Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0);
        c.wallCentre = scope.nodePositions()[static_cast<size_t>(node)] + c.lever * normal;
    };
    const double theta = 0.5;   // rad
    const double depth = 1e-3;  // m
    for (const bool side : {false, true}) {
        Colonoscope scope = straightScope(0.2);
        const int tip = scope.numInsertedNodes() - 1;
        const int mid = tip / 2;
        auto contacts = contactsOn(scope, {{mid, depth}});
        tilted(contacts, scope, mid, theta);
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, {}, side);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        ASSERT_EQ(coupling.activeNodes().size(), 1U);
        const double g = coupling.delassus()(0, 0);
        coupling.solveAndApply(scope.rod(), law());
        const Eigen::Vector3d load = coupling.loads().col(mid);
        const double lambda = load.norm();
        EXPECT_NEAR(lambda, kStiffness * depth / (1.0 + kStiffness * g), 1e-3 * lambda) << side;
        if (side) {
            EXPECT_NEAR(load.x(), 0.0, 1e-12 * lambda) << "across the shaft";
            EXPECT_GT(load.y(), 0.0);
            // n^T C d against n^T C n: the straight shaft gives way across
            // itself only (C = c e_y e_y^T there), so a load across it moves
            // the node along n by c cos(theta), one along n by c cos^2(theta).
            ContactCoupling plain(kStiffness, 1.0, kLoopStep, 1.0);
            plain.update(contacts, scope.rod(), 0, kRigidWall);
            EXPECT_NEAR(g * std::cos(theta), plain.delassus()(0, 0), 1e-6 * g);
        } else {
            EXPECT_NEAR(load.x() / load.y(), -std::tan(theta), 1e-9) << "along the wall's normal";
        }
    }
    // The tip keeps the wall's normal, and so does a node whose wall is met
    // nearly head on (its normal 0.1 across the shaft).
    const double headOn = std::acos(0.1);  // rad
    for (const bool atTip : {true, false}) {
        Colonoscope scope = straightScope(0.2);
        const int node = atTip ? scope.numInsertedNodes() - 1 : scope.numInsertedNodes() / 2;
        const double angle = atTip ? theta : headOn;
        auto contacts = contactsOn(scope, {{node, depth}});
        tilted(contacts, scope, node, angle);
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, {}, true);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), law());
        const Eigen::Vector3d load = coupling.loads().col(node);
        ASSERT_GT(load.norm(), 0.0);
        EXPECT_NEAR(load.x() / load.y(), -std::tan(angle), 1e-6) << (atTip ? "the tip" : "head on");
    }
}

namespace {

/// The turn of a frame about its own forward axis (+x on a straight scope)
/// from `before` to `after`, rad (small).
double turnAbout(const Eigen::Matrix3d& before, const Eigen::Matrix3d& after)
{
    const Eigen::Matrix3d turn = before.transpose() * after;
    return 0.5 * (turn(1, 0) - turn(0, 1));
}

}  // namespace

// Spin friction (contact.spinFriction): the friction acts where the shaft's
// surface touches the wall, r below a node pressed on a floor (normal +y).
// A shaft spinning about its axis (+x) at w slides that surface point at
// -r w along z; sliding fast, the friction is mu lambda along +z and its
// moment about the axis, (-r n) x f = -mu lambda r x, resists the spin. The
// rod carries the force at the node and the moment besides, the wall the
// opposite force; without spin friction there is no moment.
TEST(ContactCoupling, SpinFrictionActsAtTheShaftsSurface)
{
    const double mu = ContactParameters{}.frictionCoefficient;
    for (const bool spin : {false, true}) {
        Colonoscope scope = straightScope(0.15);
        const int node = scope.numInsertedNodes() / 2;
        auto contacts = contactsOn(scope, {{node, 1e-3}});
        contacts[static_cast<size_t>(node)].slip =
            Eigen::Vector3d(0.0, 0.0, -10.0);  // m/s, far past the stick
        ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, {}, false, false, spin);
        coupling.update(contacts, scope.rod(), 0, kRigidWall);
        coupling.solveAndApply(scope.rod(), frictionLaw());
        const double lambda = coupling.normalLoads()[static_cast<size_t>(node)].norm();
        ASSERT_GT(lambda, 0.0);
        const Eigen::Vector3d load = coupling.loads().col(node);
        EXPECT_NEAR(load.z(), mu * lambda, 1e-9 * lambda) << "Coulomb, against the slip";
        const Eigen::Vector3d torque = scope.rod().torque[static_cast<size_t>(node)];
        if (spin) {
            EXPECT_NEAR(torque.x(), -mu * lambda * kRadius, 1e-12) << "resists the spin";
            EXPECT_NEAR(torque.y(), 0.0, 1e-15);
            EXPECT_NEAR(torque.z(), 0.0, 1e-15);
        } else {
            EXPECT_EQ(torque.norm(), 0.0);
        }
    }
}

// The friction moments of many contacts together cannot reverse their spin
// in one step: five pressed nodes of a 30 cm shaft whose surfaces creep
// along -z (as a slow spin about +x slides them) get friction and moments
// that, with the chain at equilibrium under them, carry no node's surface
// back past where it slid from in one step: the stick's slip compliance
// bounds the moments' turn of the joints as well as the forces' push.
TEST(ContactCoupling, TheSpinFrictionOfManyContactsCannotReverseTheirSlip)
{
    Colonoscope scope = straightScope(0.3);
    const int tip = scope.numInsertedNodes() - 1;
    Eigen::MatrixXd g;
    const std::map<int, double> pressed = equalLoadDepths(scope, tip - 5, g);
    ASSERT_EQ(g.rows(), 5);
    auto contacts = contactsOn(scope, pressed);
    const double slip = 1e-4;  // m/s along -z: a creep, well inside every node's stick
    for (const auto& [node, depth] : pressed) {
        contacts[static_cast<size_t>(node)].slip = Eigen::Vector3d(0.0, 0.0, -slip);
    }
    ContactCoupling coupling(kStiffness, 1.0, kLoopStep, 1.0, {}, {}, false, false, true);
    coupling.update(contacts, scope.rod(), 0, kRigidWall);
    coupling.solveAndApply(scope.rod(), frictionLaw());
    const std::vector<Eigen::Vector3d> at(scope.nodePositions().begin(), scope.nodePositions().end());
    const std::vector<Eigen::Matrix3d> frames = scope.rod().frame;
    double torqueSum = 0.0;
    for (const auto& [node, depth] : pressed) {
        ASSERT_GT(coupling.loads().col(node).z(), 0.0) << "node " << node << ": friction against the slip";
        torqueSum += scope.rod().torque[static_cast<size_t>(node)].x();
    }
    ASSERT_LT(torqueSum, 0.0);
    for (int s = 0; s < 40; ++s) {
        scope.step();  // the chain's equilibrium under the applied loads
    }
    double back = 0.0;    // the furthest a surface point moved back along +z, m
    double turned = 0.0;  // the part of it the moments' turn gave, m
    for (const auto& [node, depth] : pressed) {
        const auto i = static_cast<size_t>(node);
        // The surface point r below the axis moves with the node and by the
        // turn about +x: a turn a moves it by a x (-r y) = -r a z.
        const double turn = -kRadius * turnAbout(frames[i], scope.rod().frame[i]);
        const double surface = (scope.nodePositions()[i] - at[i]).z() + turn;
        back = std::max(back, surface);
        turned = std::max(turned, turn);
    }
    RecordProperty("surface_back_m", std::to_string(back));
    EXPECT_GT(turned, 0.0) << "the moments turn the shaft against its spin";
    EXPECT_GT(back, 0.0);
    EXPECT_LT(back, slip * kLoopStep) << "the friction threw a surface back past where it slid from";
}
