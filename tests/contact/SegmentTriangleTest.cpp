// Narrow phase: table of capsule axes against one wall triangle with the
// expected contacts (iMSTK habit), and continuous detection of a node
// passing through the wall.

#include "simcore/contact/SegmentTriangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace colonosim::contact {
namespace {

/// Scope radius, m.
constexpr double kRadius = 6.5e-3;
/// Depths and points are sums of a few millimetre-scale doubles: 1 nm is far above rounding.
constexpr double kTolerance = 1e-9;

/// A 20 mm right triangle in the plane z = 0, counter-clockwise seen from -z:
/// its outward normal is -z, so the lumen is z > 0.
const Eigen::Vector3d kA(0.0, 0.0, 0.0);
const Eigen::Vector3d kB(0.0, 0.02, 0.0);
const Eigen::Vector3d kC(0.02, 0.0, 0.0);

struct ProximityCase {
    std::string name;
    Eigen::Vector3d p0;
    Eigen::Vector3d p1;
    bool degenerate;  ///< use the collinear triangle (0,0,0), (10,0,0), (20,0,0) mm
    bool contact;     ///< expected: the capsule touches (d < r)
    double depth;     ///< expected r - d, m (when contact)
    Eigen::Vector3d normal;
    double segmentParam;  ///< expected t, or < 0 to skip
    FeatureRegion region;
};

class SegmentTriangleTable : public ::testing::TestWithParam<ProximityCase> {};

TEST_P(SegmentTriangleTable, ExpectedContact)
{
    const ProximityCase& c = GetParam();
    const SegmentTriangleProximity p =
        c.degenerate ? segmentTriangleProximity(c.p0, c.p1, {0, 0, 0}, {0.01, 0, 0}, {0.02, 0, 0})
                     : segmentTriangleProximity(c.p0, c.p1, kA, kB, kC);
    const bool contact = p.found && p.signedDistance < kRadius;
    ASSERT_EQ(contact, c.contact);
    if (!c.contact) {
        return;
    }
    EXPECT_NEAR(kRadius - p.signedDistance, c.depth, kTolerance);
    EXPECT_NEAR((p.normal - c.normal.normalized()).norm(), 0.0, 1e-9);
    EXPECT_EQ(p.region, c.region);
    if (c.segmentParam >= 0.0) {
        EXPECT_NEAR(p.segmentParam, c.segmentParam, 1e-9);
    }
    // The reported points agree with the reported distance and barycentric coordinates.
    EXPECT_NEAR((p.axisPoint - (c.p0 + p.segmentParam * (c.p1 - c.p0))).norm(), 0.0, kTolerance);
    EXPECT_NEAR(std::abs(p.signedDistance), (p.axisPoint - p.wallPoint).norm(), kTolerance);
    if (!c.degenerate) {
        EXPECT_NEAR(p.barycentric.sum(), 1.0, 1e-12);
        const Eigen::Vector3d fromBary =
            p.barycentric[0] * kA + p.barycentric[1] * kB + p.barycentric[2] * kC;
        EXPECT_NEAR((fromBary - p.wallPoint).norm(), 0.0, kTolerance);
    }
}

const double kEdgeGap = std::sqrt(2 * 9e-6 + 4e-6);  // |(3, 3, 2) mm|
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

INSTANTIATE_TEST_SUITE_P(Cases, SegmentTriangleTable,
                         ::testing::Values(ProximityCase{"FarAway",
                                                         {0.005, 0.005, 0.05},
                                                         {0.006, 0.005, 0.06},
                                                         false,
                                                         false,
                                                         0,
                                                         kZ,
                                                         -1,
                                                         FeatureRegion::Face},
                                           ProximityCase{"JustOutOfReach",
                                                         {0.005, 0.005, 0.0066},
                                                         {0.005, 0.005, 0.02},
                                                         false,
                                                         false,
                                                         0,
                                                         kZ,
                                                         -1,
                                                         FeatureRegion::Face},
                                           ProximityCase{"Touching",
                                                         {0.005, 0.005, 0.0064},
                                                         {0.005, 0.005, 0.02},
                                                         false,
                                                         true,
                                                         1e-4,
                                                         kZ,
                                                         0.0,
                                                         FeatureRegion::Face},
                                           ProximityCase{"Penetrating",
                                                         {0.005, 0.004, 0.003},
                                                         {0.004, 0.005, 0.01},
                                                         false,
                                                         true,
                                                         3.5e-3,
                                                         kZ,
                                                         0.0,
                                                         FeatureRegion::Face},
                                           ProximityCase{"AxisThroughWall",
                                                         {0.005, 0.005, 0.004},
                                                         {0.005, 0.005, -0.002},
                                                         false,
                                                         true,
                                                         8.5e-3,
                                                         kZ,
                                                         1.0,
                                                         FeatureRegion::Face},
                                           ProximityCase{"EdgeRegion",
                                                         {0.011, 0.015, 0.002},
                                                         {0.015, 0.011, 0.002},
                                                         false,
                                                         true,
                                                         kRadius - kEdgeGap,
                                                         {3, 3, 2},
                                                         -1,
                                                         FeatureRegion::Edge},
                                           ProximityCase{"VertexRegion",
                                                         {-0.003, -0.003, 0.002},
                                                         {-0.01, -0.01, 0.002},
                                                         false,
                                                         true,
                                                         kRadius - kEdgeGap,
                                                         {-3, -3, 2},
                                                         0.0,
                                                         FeatureRegion::Vertex},
                                           ProximityCase{"BehindNeighbourRegion",
                                                         {0.03, 0.03, -0.001},
                                                         {0.035, 0.03, -0.001},
                                                         false,
                                                         false,
                                                         0,
                                                         kZ,
                                                         -1,
                                                         FeatureRegion::Face},
                                           ProximityCase{"ParallelOverFace",
                                                         {0.002, 0.002, 0.004},
                                                         {0.008, 0.008, 0.004},
                                                         false,
                                                         true,
                                                         2.5e-3,
                                                         kZ,
                                                         0.5,
                                                         FeatureRegion::Face},
                                           ProximityCase{"ParallelPartlyOverFace",
                                                         {-0.01, 0.005, 0.004},
                                                         {0.005, 0.005, 0.004},
                                                         false,
                                                         true,
                                                         2.5e-3,
                                                         kZ,
                                                         5.0 / 6.0,
                                                         FeatureRegion::Face},
                                           ProximityCase{"DegenerateTriangle",
                                                         {0.005, 0.004, -0.002},
                                                         {0.005, 0.004, 0.002},
                                                         true,
                                                         true,
                                                         2.5e-3,
                                                         Eigen::Vector3d::UnitY(),
                                                         -1,
                                                         FeatureRegion::Edge},
                                           ProximityCase{"DegenerateTriangleFar",
                                                         {0.0, 0.01, 0.0},
                                                         {0.02, 0.01, 0.0},
                                                         true,
                                                         false,
                                                         0,
                                                         kZ,
                                                         -1,
                                                         FeatureRegion::Edge},
                                           ProximityCase{"PointSegment",
                                                         {0.005, 0.005, 0.001},
                                                         {0.005, 0.005, 0.001},
                                                         false,
                                                         true,
                                                         5.5e-3,
                                                         kZ,
                                                         -1,
                                                         FeatureRegion::Face}),
                         [](const ::testing::TestParamInfo<ProximityCase>& info) { return info.param.name; });

struct CrossingCase {
    std::string name;
    Eigen::Vector3d p0;
    Eigen::Vector3d p1;
    bool crossed;
    double t;
};

class CrossingTable : public ::testing::TestWithParam<CrossingCase> {};

TEST_P(CrossingTable, DetectsInsideToOutside)
{
    const CrossingCase& c = GetParam();
    const WallCrossing w = pointCrossesTriangle(c.p0, c.p1, kA, kB, kC);
    ASSERT_EQ(w.crossed, c.crossed);
    if (c.crossed) {
        EXPECT_NEAR(w.t, c.t, 1e-12);
        EXPECT_NEAR(w.point.z(), 0.0, 1e-15);
        EXPECT_NEAR((w.normal - kZ).norm(), 0.0, 1e-12);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CrossingTable,
    ::testing::Values(
        CrossingCase{"FastThroughFace", {0.005, 0.005, 0.001}, {0.005, 0.005, -0.003}, true, 0.25},
        CrossingCase{"OutsideToInside", {0.005, 0.005, -0.001}, {0.005, 0.005, 0.003}, false, 0},
        CrossingCase{"StaysInside", {0.005, 0.005, 0.004}, {0.005, 0.005, 0.001}, false, 0},
        CrossingCase{"BesideTheTriangle", {0.03, 0.03, 0.001}, {0.03, 0.03, -0.001}, false, 0},
        CrossingCase{"ThroughSharedEdge", {0.01, 0.01, 0.001}, {0.01, 0.01, -0.001}, true, 0.5},
        CrossingCase{"ThroughVertex", {0.0, 0.0, 0.002}, {0.0, 0.0, -0.002}, true, 0.5},
        CrossingCase{"FromThePlane", {0.005, 0.005, 0.0}, {0.005, 0.005, -0.001}, true, 0.0}),
    [](const ::testing::TestParamInfo<CrossingCase>& info) { return info.param.name; });

}  // namespace
}  // namespace colonosim::contact
