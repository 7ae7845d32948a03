// The lumen as a chain of rings (LumenTube) and the contact measured on it
// (LumenContact), on the default procedural colon at rest.

#include "simcore/contact/LumenContact.h"
#include "../physics/TubeAnatomy.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/params/Parameter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace colonosim::contact {
namespace {

const geometry::ColonAnatomy& colon()
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return anatomy;
}

LumenTube restTube()
{
    LumenTube tube(colon());
    tube.update(colon().physicsMesh.vertices);
    return tube;
}

// Wall nodes in `tube`'s layout: ring i's nodes on a circle of `radius`
// about centreOf(i), in the plane of z and (sin t, cos t, 0) with t =
// tiltOf(i) (rad; none: the y-z plane), and the apex at `apex`.
Eigen::Matrix3Xd ringWall(const LumenTube& tube, const std::function<Eigen::Vector3d(int)>& centreOf,
                          double radius, const Eigen::Vector3d& apex,
                          const std::function<double(int)>& tiltOf = {})
{
    const int perRing = tube.nodesPerRing();
    Eigen::Matrix3Xd wall(3, tube.numRings() * perRing + 1);
    for (int ring = 0; ring < tube.numRings(); ++ring) {
        const double turn = tiltOf ? tiltOf(ring) : 0.0;
        const Eigen::Vector3d across(std::sin(turn), std::cos(turn), 0.0);
        for (int j = 0; j < perRing; ++j) {
            const double angle = 2.0 * std::numbers::pi * j / perRing;
            wall.col(ring * perRing + j) =
                centreOf(ring) +
                radius * (std::cos(angle) * across + std::sin(angle) * Eigen::Vector3d::UnitZ());
        }
    }
    wall.col(tube.apex()) = apex;
    return wall;
}

// Every ring centre lies in its own section, found by walking from the anus,
// and the stations' arc lengths grow along the colon.
TEST(LumenTube, RingCentresAreFoundInTheirSectionsInOrder)
{
    const LumenTube tube = restTube();
    ASSERT_GT(tube.numRings(), 50);
    double previous = -1.0;
    int start = 0;
    for (int ring = 1; ring + 1 < tube.numRings(); ++ring) {
        const Eigen::Vector3d p = 0.5 * (tube.centre(ring) + tube.centre(ring + 1));
        const LumenStation at = tube.locate(p, start);
        EXPECT_EQ(at.ring, ring) << "midpoint of section " << ring;
        EXPECT_GE(at.u, 0.0);
        EXPECT_LE(at.u, 1.0);
        const double s = tube.arcLength(at);
        EXPECT_GT(s, previous) << "section " << ring;
        previous = s;
        start = at.ring;
    }
}

// The colon folded into a hairpin (a flattened ring at a bend, as the
// scope's push makes at the sigmoid-descending junction): the two legs run
// 20 mm apart, so a point 12 mm off its own leg's axis lies 8 mm from the
// other leg, within the search's four sections. The station follows the
// point along its own leg and does not cross the fold to the nearer one,
// which would put the point in the other leg's lumen and push it on through
// the wall.
TEST(LumenTube, APointBesideAFoldStaysInItsOwnLegOfTheColon)
{
    LumenTube tube = restTube();
    const int fold = 40;           // the last ring of the first leg
    const double spacing = 0.014;  // m between ring centres
    const double legs = 0.020;     // m between the legs' axes
    const double radius = 0.006;   // m, a flattened lumen
    const auto centreOf = [&](int ring) {
        // Out along +x to the fold, then back along -x, 20 mm to the side.
        const bool back = ring > fold;
        const double x = back ? (2 * fold + 1 - ring) * spacing : ring * spacing;
        return Eigen::Vector3d(x, back ? legs : 0.0, 0.0);
    };
    tube.update(ringWall(tube, centreOf, radius, Eigen::Vector3d(-0.05, legs, 0.0)));

    const int own = fold - 2;  // section (38, 39) of the first leg
    const Eigen::Vector3d p((own + 0.5) * spacing, 0.012, 0.0);
    const double toOther = 0.008;  // m from p to the second leg's axis
    ASSERT_NEAR((p - Eigen::Vector3d(p.x(), legs, 0.0)).norm(), toOther, 1e-12);
    const LumenStation at = tube.locate(p, own);
    EXPECT_EQ(at.ring, own) << "the station crossed the fold";
    EXPECT_NEAR(at.u, 0.5, 1e-9);
    // From a section back on its own leg the walk reaches it, and stops there.
    EXPECT_EQ(tube.locate(p, own - 1).ring, own);
    const LumenWallSample w = tube.wallAt(p, at);
    EXPECT_NEAR(w.distance, 0.012, 1e-9) << "measured from its own leg's axis";
    EXPECT_GT(w.radial.y(), 0.99) << "pushed back towards its own axis, not on through the fold";
}

// A point driven straight out through the wall at 0.5 m/s (0.5 mm per 1 ms
// step) stays in its section or the next (ring planes meet on the inside of
// a bend), its depth grows by the distance moved, and the normal keeps
// pointing back towards the axis: the wall cannot be tunnelled, however far
// the point goes.
TEST(LumenContact, APointDrivenThroughTheWallIsPushedBackTheWayItCame)
{
    const LumenTube tube = restTube();
    const int ring = 30;
    const Eigen::Vector3d centre = 0.5 * (tube.centre(ring) + tube.centre(ring + 1));
    const Eigen::Vector3d axis = tube.axis(ring);
    Eigen::Vector3d out = axis.unitOrthogonal();
    constexpr double kScopeRadius = 0.0065;  // m
    const double step = 0.5e-3;              // m per loop step
    int start = ring;
    double lastDepth = -1.0;
    // 37 mm out: 20 mm past the wall, far beyond what a step can push the
    // scope in (on the axis itself the way out is undefined).
    for (int k = 1; k < 75; ++k) {
        const Eigen::Vector3d p = centre + (k * step) * out;
        const LumenStation at = tube.locate(p, start);
        ASSERT_LE(std::abs(at.ring - ring), 1) << "left its section at " << k * step * 1e3 << " mm";
        const LumenWallSample w = tube.wallAt(p, at);
        const double depth = w.distance + kScopeRadius - w.wallRadius;
        if (k > 1) {
            EXPECT_NEAR(depth - lastDepth, step, 0.2 * step) << "at " << k * step * 1e3 << " mm";
        }
        // The normal (-radial) is perpendicular to the section's interpolated
        // axis, which turns with the bend (by up to the section's bend angle
        // once the point counts in the next section): it points back the way in.
        EXPECT_GT(w.radial.dot(out), 0.8) << "at " << k * step * 1e3 << " mm";
        lastDepth = depth;
        start = at.ring;
    }
    EXPECT_GT(lastDepth, 0.015) << "the point ended far outside the wall, and still knows it";
}

// LumenContact gives every scope node an entry: a shaft along the ring
// centres from the anus is clear of the wall everywhere, and a tip pushed
// 5 cm out through the wall has a positive depth and a normal back into the
// lumen, with its wall point's weights summing to 1.
TEST(LumenContact, AShaftOnTheAxisIsClearAndATipThroughTheWallIsPushedBack)
{
    LumenContact contact(colon(), ContactParameters{});
    const LumenTube tube = restTube();
    constexpr int kRings = 12;
    const Eigen::Vector3d out = tube.axis(kRings).unitOrthogonal();
    const double r = 0.0065;  // m
    Eigen::Matrix3Xd scope(3, kRings + 2);
    for (int ring = 0; ring <= kRings; ++ring) {
        scope.col(ring) = tube.centre(ring) + 1e-3 * tube.axis(ring);  // just inside each section
    }
    scope.col(kRings + 1) = 0.5 * (tube.centre(kRings) + tube.centre(kRings + 1)) + 0.05 * out;
    const Eigen::Matrix3Xd& wall = colon().physicsMesh.vertices;
    const auto& result = contact.compute(scope, Eigen::Matrix3Xd::Zero(3, scope.cols()), r, wall,
                                         Eigen::Matrix3Xd::Zero(3, wall.cols()));
    ASSERT_EQ(result.size(), static_cast<size_t>(kRings + 2));
    for (int i = 0; i <= kRings; ++i) {
        EXPECT_LT(result[static_cast<size_t>(i)].depth, 0.0) << "node " << i;
    }
    const LumenNodeContact& tip = result.back();
    EXPECT_EQ(tip.station.ring, kRings);
    EXPECT_GT(tip.depth, 0.02);
    EXPECT_LT(tip.normal.dot(out), -0.98);
    double weights = 0.0;
    for (const double w : tip.weights) {
        weights += w;
    }
    EXPECT_NEAR(weights, 1.0, 1e-12);
}

// Where the colon is pleated on the shaft, consecutive scope nodes can lie
// more sections apart than the search around a neighbour reaches. A node
// that slides 0.5 mm per step from section 3 to section 15 while its base-side
// neighbour stays in section 2 is followed by its own history; searched only
// around the neighbour it would be lost at section 6.
TEST(LumenContact, ANodeIsFollowedFromItsOwnLastStationNotOnlyItsNeighbours)
{
    const LumenTube tube = restTube();
    const Eigen::Matrix3Xd& wall = colon().physicsMesh.vertices;
    const Eigen::Matrix3Xd still = Eigen::Matrix3Xd::Zero(3, wall.cols());
    const auto midpoint = [&](int ring) {
        return Eigen::Vector3d(0.5 * (tube.centre(ring) + tube.centre(ring + 1)));
    };
    Eigen::Matrix3Xd scope(3, 2);
    scope.col(0) = midpoint(2);
    scope.col(1) = midpoint(3);
    LumenContact followed(colon(), ContactParameters{});
    LumenContact searched(colon(), ContactParameters{});
    const Eigen::Matrix3Xd velocities = Eigen::Matrix3Xd::Zero(3, 2);
    for (int ring = 3; ring < 15; ++ring) {
        const Eigen::Vector3d from = midpoint(ring);
        const Eigen::Vector3d to = midpoint(ring + 1);
        const int steps = static_cast<int>(std::ceil((to - from).norm() / 5e-4));
        for (int k = 1; k <= steps; ++k) {
            scope.col(1) = from + (to - from) * (static_cast<double>(k) / steps);
            followed.compute(scope, velocities, 0.0065, wall, still, 0);
            searched.compute(scope, velocities, 0.0065, wall, still);
        }
    }
    EXPECT_EQ(followed.contacts()[1].station.ring, 15);
    EXPECT_LT(followed.contacts()[1].depth, 0.0) << "inside the lumen";
    EXPECT_EQ(searched.contacts()[1].station.ring, 6) << "the neighbour's search reaches four sections";
    EXPECT_GT(searched.contacts()[1].depth, followed.contacts()[1].depth);
}

// The colon dragged into a Z of three legs on the withdrawal (rings 0-10 out
// along +x, 11-20 back along -x 20 mm to the side, 21 on along +x): the tip's
// station was on the middle leg (it went round the fold), and the colon has
// moved so that the tip now lies on the first leg's axis, in section 6.
// Walking from section 15 along the middle leg it is held at section 14,
// beside it across the wall, where its centre lies outside the wall (the
// lost station of the expert's way back, which was then pushed towards the
// wrong part of the colon); on towards its base-side neighbour (section 5)
// the first leg's section 6 holds it, and that is its station.
// A node pushed through the first leg's wall into the middle leg is not
// moved on (the section that holds it lies away from its neighbour): it is
// pushed back the way it came.
TEST(LumenContact, ANodeHeldAtAFoldFindsTheSectionThatHoldsIt)
{
    LumenTube tube = restTube();
    const int perRing = tube.nodesPerRing();
    const double spacing = 0.014;  // m between ring centres
    const double legs = 0.020;     // m between the legs' axes
    const double radius = 0.009;   // m
    const auto centreOf = [&](int ring) {
        if (ring <= 10) {
            return Eigen::Vector3d(ring * spacing, 0.0, 0.0);
        }
        if (ring <= 20) {
            return Eigen::Vector3d((21 - ring) * spacing, legs, 0.0);
        }
        return Eigen::Vector3d((ring - 20) * spacing, 2.0 * legs, 0.0);
    };
    const Eigen::Matrix3Xd wall =
        ringWall(tube, centreOf, radius, centreOf(tube.numRings()) + Eigen::Vector3d(spacing, 0.0, 0.0));
    tube.update(wall);
    const Eigen::Matrix3Xd still = Eigen::Matrix3Xd::Zero(3, wall.cols());
    const Eigen::Matrix3Xd velocities = Eigen::Matrix3Xd::Zero(3, 2);
    const auto midpoint = [&](int ring) {
        return Eigen::Vector3d(0.5 * (centreOf(ring) + centreOf(ring + 1)));
    };
    constexpr double kScopeRadius = 0.0065;  // m

    LumenContact contact(colon(), ContactParameters{});
    Eigen::Matrix3Xd scope(3, 2);
    scope.col(0) = midpoint(5);
    scope.col(1) = midpoint(6);
    contact.compute(scope, velocities, kScopeRadius, wall, still);
    for (int ring = 6; ring < 15; ++ring) {  // the tip goes on round the fold, 0.5 mm a step
        const Eigen::Vector3d from = midpoint(ring);
        const Eigen::Vector3d to = midpoint(ring + 1);
        const int steps = static_cast<int>(std::ceil((to - from).norm() / 5e-4));
        for (int k = 1; k <= steps; ++k) {
            scope.col(1) = from + (to - from) * (static_cast<double>(k) / steps);
            contact.compute(scope, velocities, kScopeRadius, wall, still, 0);
        }
    }
    ASSERT_EQ(contact.contacts()[1].station.ring, 15);
    scope.col(1) = midpoint(6);
    ASSERT_EQ(tube.locate(scope.col(1), 15, 1).ring, 14) << "the walk is held across the wall";
    contact.compute(scope, velocities, kScopeRadius, wall, still, 0);
    const LumenNodeContact& tip = contact.contacts()[1];
    EXPECT_EQ(tip.station.ring, 6);
    EXPECT_NEAR(tip.station.u, 0.5, 1e-9);
    // On its own section's axis: the wall (a polygon of P nodes) lies
    // between R cos(pi / P) and R from it.
    const double inscribed = radius * std::cos(std::numbers::pi / perRing);
    EXPECT_GE(tip.depth, kScopeRadius - radius - 1e-12);
    EXPECT_LE(tip.depth, kScopeRadius - inscribed + 1e-12);

    // Through the first leg's wall, 3 mm into the middle leg's lumen, with
    // and without the pleat search (the segment from the neighbour leaves
    // the lumen: it crosses no ring of the middle leg).
    for (const double pleatSearch : {0.0, 1.0}) {
        ContactParameters parameters;
        parameters.pleatSearch = pleatSearch;
        LumenContact pushed(colon(), parameters);
        scope.col(1) = midpoint(6);
        pushed.compute(scope, velocities, kScopeRadius, wall, still);
        ASSERT_EQ(pushed.contacts()[1].station.ring, 6);
        scope.col(1) = midpoint(6) + Eigen::Vector3d(0.0, legs - 0.003, 0.0);
        pushed.compute(scope, velocities, kScopeRadius, wall, still, 0);
        const LumenNodeContact& through = pushed.contacts()[1];
        EXPECT_EQ(through.station.ring, 6) << "moved on into the middle leg, pleat search " << pleatSearch;
        EXPECT_GE(through.depth, legs - 0.003 + kScopeRadius - radius - 1e-12);
        EXPECT_LE(through.depth, legs - 0.003 + kScopeRadius - inscribed + 1e-12);
        EXPECT_LT(through.normal.y(), -0.99) << "pushed back towards the first leg's axis";
    }
}

// The colon pleated on the shaft, as the expert's shortening gathers the
// sigmoid: rings 11-30 packed 2 mm apart along the shaft, the first five of
// them tilted 80 degrees (folds of the pleat lying along the shaft), so that
// across the centre line's axis their sections are flattened to 1.6 mm. A
// point 4 mm beside the shaft's line in section 18 lies inside that
// section, 18 mm on from its base-side neighbour in section 9; the walk from
// the neighbour's section (four sections at most) stops in the tilted rings
// with the point outside their wall, and no section nearer the neighbour
// holds it (the seed-1 swing: points measured 30-58 mm into sections they
// did not lie in, pushed along the shaft). The shaft's segment from the
// neighbour passes through every ring in between within the scope's radius
// of its wall, so with contact.pleatSearch 1 the section that holds the
// point is taken although it lies away from the neighbour: the point is
// measured from that section's axis, its side on the wall 4 mm away. A
// point pushed through the wall into a neighbouring loop is still pushed
// back (ANodeHeldAtAFoldFindsTheSectionThatHoldsIt): that segment leaves
// the lumen.
TEST(LumenContact, APointInAPleatIsFoundThroughThePackedRings)
{
    LumenTube tube = restTube();
    const int perRing = tube.nodesPerRing();
    const double spacing = 0.014;  // m between ring centres outside the pleat
    const double packed = 0.002;   // m between ring centres in the pleat
    const double radius = 0.009;   // m
    const double tilt = 80.0 * std::numbers::pi / 180.0;
    const int first = 11;
    const int last = 30;
    const auto centreOf = [&](int ring) {
        const double start = (first - 1) * spacing;
        if (ring < first) {
            return Eigen::Vector3d(ring * spacing, 0.0, 0.0);
        }
        if (ring <= last) {
            return Eigen::Vector3d(start + (ring - first + 1) * packed, 0.0, 0.0);
        }
        return Eigen::Vector3d(start + (last - first + 1) * packed + (ring - last) * spacing, 0.0, 0.0);
    };
    const Eigen::Matrix3Xd wall =
        ringWall(tube, centreOf, radius, centreOf(tube.numRings()) + Eigen::Vector3d(spacing, 0.0, 0.0),
                 [&](int ring) { return ring >= first && ring < first + 5 ? tilt : 0.0; });
    tube.update(wall);
    const Eigen::Matrix3Xd still = Eigen::Matrix3Xd::Zero(3, wall.cols());
    const Eigen::Matrix3Xd velocities = Eigen::Matrix3Xd::Zero(3, 11);
    constexpr double kScopeRadius = 0.0065;  // m

    const Eigen::Vector3d base(9.9 * spacing, 0.0, 0.0);  // section 9
    const Eigen::Vector3d p(0.5 * (centreOf(18).x() + centreOf(19).x()), 0.004, 0.0);
    ASSERT_NEAR((p - base).norm(), 0.0188, 1e-4);
    LumenStation inside;
    ASSERT_TRUE(tube.holds(p, 18, inside));
    const LumenStation held = tube.locate(p, 9, 4);
    const LumenWallSample heldWall = tube.wallAt(p, held);
    ASSERT_GT(heldWall.distance, heldWall.wallRadius) << "held at section " << held.ring;
    ASSERT_LT(held.ring, 18);
    LumenStation found;
    ASSERT_FALSE(tube.findHolding(p, held.ring, 9, 16, found)) << "found at section " << found.ring;
    EXPECT_TRUE(tube.passesThrough(base, p, 9, 18, kScopeRadius));

    // The shaft on the axis from the anus (each point searches around its
    // base-side neighbour's section), its last two points the neighbour and p.
    ContactParameters pleats;
    pleats.pleatSearch = 1.0;
    LumenContact contact(colon(), pleats);
    ContactParameters noPleats;
    noPleats.pleatSearch = 0.0;
    LumenContact without(colon(), noPleats);
    Eigen::Matrix3Xd scope(3, 11);
    for (int k = 0; k < 9; ++k) {
        scope.col(k) = Eigen::Vector3d((k + 0.5) * spacing, 0.0, 0.0);
    }
    scope.col(9) = base;
    scope.col(10) = p;
    const auto& contacts = contact.compute(scope, velocities, kScopeRadius, wall, still);
    ASSERT_EQ(contacts[9].station.ring, 9);
    const LumenNodeContact& c = contacts[10];
    EXPECT_GE(c.station.ring, 16);
    EXPECT_LE(c.station.ring, 19);
    // Measured from its own section's axis, 4 mm away: the scope's side
    // meets the wall (a polygon of P nodes, between R cos(pi / P) and R from
    // the axis), pushed back across the shaft, not along it.
    const double inscribed = radius * std::cos(std::numbers::pi / perRing);
    EXPECT_GE(c.depth, 0.004 + kScopeRadius - radius - 1e-12);
    EXPECT_LE(c.depth, 0.004 + kScopeRadius - inscribed + 1e-12);
    EXPECT_LT(c.normal.y(), -0.99);
    // Without the pleat search (contact.pleatSearch 0) it stays where the
    // walk held it, measured much deeper.
    const LumenNodeContact& h = without.compute(scope, velocities, kScopeRadius, wall, still)[10];
    EXPECT_EQ(h.station.ring, held.ring);
    EXPECT_NEAR(h.depth, heldWall.distance + kScopeRadius - heldWall.wallRadius, 1e-12);
    EXPECT_GT(h.depth, c.depth + 0.005);

    // 20 mm beside the shaft's line the segment from the neighbour crosses
    // the packed rings' planes outside their wall (9 mm) and the scope's radius.
    const Eigen::Vector3d beside = p + Eigen::Vector3d(0.0, 0.0, 0.020);
    EXPECT_FALSE(tube.passesThrough(base, beside, 9, 18, kScopeRadius));
}

// The closed cecal end: the contact compute() gives a node at `p` at the
// tip of a shaft along the ring centres from the anus (each node searches
// around its base-side neighbour's section).
LumenNodeContact endContact(const Eigen::Vector3d& p, double radius)
{
    LumenContact contact(colon(), ContactParameters{});
    const LumenTube& tube = contact.tube();
    const int sections = tube.numRings() - 1;
    Eigen::Matrix3Xd scope(3, sections + 1);
    for (int ring = 0; ring < sections; ++ring) {
        scope.col(ring) = tube.centre(ring) + 1e-3 * tube.axis(ring);
    }
    scope.col(sections) = p;
    const Eigen::Matrix3Xd& wall = colon().physicsMesh.vertices;
    return contact
        .compute(scope, Eigen::Matrix3Xd::Zero(3, scope.cols()), radius, wall,
                 Eigen::Matrix3Xd::Zero(3, wall.cols()))
        .back();
}

// Beyond the dome ring the lumen is closed by the mesh's own cone from the
// dome ring to the apex: a point on one of its edges lies on the wall (depth
// equal to the scope's radius), and its load goes to the apex and the dome
// ring's node in proportion to where it lies along the edge.
TEST(LumenContact, TheClosedEndIsTheConeFromTheDomeRingToTheApex)
{
    const LumenTube tube = restTube();
    const int last = tube.numRings() - 1;
    const Eigen::Matrix3Xd& rest = colon().physicsMesh.vertices;
    const Eigen::Vector3d apex = rest.col(tube.apex());
    constexpr double kScopeRadius = 0.0065;  // m
    for (int j = 0; j < tube.nodesPerRing(); j += 3) {
        const Eigen::Vector3d ringNode = rest.col(tube.node(last, j));
        for (const double t : {0.2, 0.4, 0.6}) {  // from the apex towards the ring
            const Eigen::Vector3d p = apex + t * (ringNode - apex);
            const LumenNodeContact c = endContact(p, kScopeRadius);
            ASSERT_TRUE(c.endCap) << "node " << j << " at " << t;
            EXPECT_NEAR(c.depth, kScopeRadius, 1e-9) << "node " << j << " at " << t;
            // The normal is the cone's: mostly back along the axis.
            EXPECT_LT(c.normal.dot(tube.axis(last)), -0.9) << "node " << j << " at " << t;
            double onApex = 0.0;
            double onNode = 0.0;
            double sum = 0.0;
            for (size_t k = 0; k < 4; ++k) {
                onApex += c.wallNodes[k] == tube.apex() ? c.weights[k] : 0.0;
                onNode += c.wallNodes[k] == tube.node(last, j) ? c.weights[k] : 0.0;
                sum += c.weights[k];
            }
            EXPECT_NEAR(sum, 1.0, 1e-12);
            EXPECT_NEAR(onApex, 1.0 - t, 1e-9) << "node " << j << " at " << t;
            EXPECT_NEAR(onNode, t, 1e-9) << "node " << j << " at " << t;
        }
    }
}

// A node pressed outwards past the dome ring, just beyond its plane, meets
// the side wall and the end's cone at their corner (70-80 degrees apart).
// Its normal turns with it round the rounded corner, by under 5 degrees
// per 0.5 mm, instead of jumping from one wall to the other, which would drop
// the load it carries; its depth grows no faster than it moves; and
// depthAt() re-measures the same contact.
TEST(LumenContact, TheCornerOfTheClosedEndTurnsTheNormalSmoothly)
{
    const LumenTube tube = restTube();
    const int last = tube.numRings() - 1;
    const Eigen::Vector3d axis = tube.axis(last);
    const Eigen::Vector3d out = axis.unitOrthogonal();
    const Eigen::Vector3d start = tube.centre(last) + 1e-3 * axis;
    constexpr double kScopeRadius = 0.0065;  // m
    constexpr double kStep = 0.5e-3;         // m
    Eigen::Vector3d lastNormal = Eigen::Vector3d::Zero();
    double lastDepth = 0.0;
    double turnedMost = 0.0;
    double firstDot = 0.0;
    for (int k = 0; k <= 60; ++k) {  // 30 mm out: from inside the ring to outside the wall
        const Eigen::Vector3d p = start + k * kStep * out;
        const LumenNodeContact c = endContact(p, kScopeRadius);
        ASSERT_TRUE(c.endCap) << "at " << k * kStep * 1e3 << " mm";
        Eigen::Vector3d n;
        EXPECT_NEAR(c.depthAt(p, n), c.depth, 1e-12);
        EXPECT_LT((n - c.normal).norm(), 1e-12);
        if (k == 1) {
            firstDot = c.normal.dot(out);
        }
        if (k > 1) {  // (on the axis itself, the cone's apex, the normal has no side)
            turnedMost = std::max(turnedMost, std::acos(std::clamp(c.normal.dot(lastNormal), -1.0, 1.0)));
        }
        if (k > 0) {
            EXPECT_LE(c.depth - lastDepth, kStep * (1.0 + 1e-9)) << "at " << k * kStep * 1e3 << " mm";
        }
        lastNormal = c.normal;
        lastDepth = c.depth;
    }
    // It went from the cone's normal (nearly along the axis) to the side
    // wall's (back towards the axis), turning at most 5 degrees a step.
    EXPECT_GT(firstDot, -0.35);
    EXPECT_LT(lastNormal.dot(out), -0.95);
    EXPECT_LT(turnedMost, 5.0 * std::numbers::pi / 180.0);
    EXPECT_GT(lastDepth, 0.0);
}

// A mesh that is not a tube of rings closed by an apex is refused by name.
TEST(LumenTube, RefusesAMeshWithoutAnApex)
{
    try {
        LumenTube tube(physics::testing::makeTubeAnatomy({}));
        ADD_FAILURE() << "a tube without an apex was accepted";
    } catch (const params::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("physics mesh"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace colonosim::contact
