#include "simcore/geometry/ColonLayout.h"

#include "simcore/geometry/CentrelineSampling.h"

#include "SegmentLengths.h"
#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::geometry {
namespace {

struct LayoutCase {
    const char* name;
    std::array<double, kNumSegments> lengths;  // m, rectum -> cecum
};

using testing::withLengths;

class ColonLayoutCase : public ::testing::TestWithParam<LayoutCase> {};

TEST_P(ColonLayoutCase, EachSegmentHasItsDeclaredLengthWithin1Percent)
{
    const AnatomyParameters p = withLengths(GetParam().lengths);
    const ColonLayout layout = layoutColon(p);
    for (int i = 0; i < kNumSegments; ++i) {
        const double declared = p.length(static_cast<Segment>(i));
        const double actual = layout.segmentStart[static_cast<std::size_t>(i) + 1] -
                              layout.segmentStart[static_cast<std::size_t>(i)];
        EXPECT_NEAR(actual, declared, 0.01 * declared) << segmentName(static_cast<Segment>(i));
    }
    EXPECT_NEAR(layout.centreline.length(), p.totalLength(), 0.01 * p.totalLength());
}

TEST_P(ColonLayoutCase, FramesAreOrthonormalAndRotationMinimising)
{
    const ColonLayout layout = layoutColon(withLengths(GetParam().lengths));
    const Centreline& c = layout.centreline;
    ASSERT_GT(c.numPoints(), 1000);
    double totalTwist = 0.0;
    double totalTurn = 0.0;
    for (int i = 0; i + 1 < c.numPoints(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        ASSERT_NEAR(c.tangents[k].norm(), 1.0, 1e-9);
        ASSERT_NEAR(c.normals[k].norm(), 1.0, 1e-9);
        ASSERT_NEAR(c.tangents[k].dot(c.normals[k]), 0.0, 1e-9);
        // Parallel transport has no twist: the change of the normal has no
        // component along the mean binormal (accumulated below).
        const Eigen::Vector3d b =
            c.tangents[k].cross(c.normals[k]) + c.tangents[k + 1].cross(c.normals[k + 1]);
        totalTwist += std::abs((c.normals[k + 1] - c.normals[k]).dot(0.5 * b));
        totalTurn += (c.tangents[k + 1] - c.tangents[k]).norm();
        // Radius changes smoothly: < 0.5 mm per 1 mm step (the steepest is the
        // narrowing at a sharp flexure, spread over +-25 mm).
        EXPECT_LT(std::abs(c.radius[k + 1] - c.radius[k]), 5e-4);
        // No bend sharper than the lumen is wide (the rings would cross).
        if (i > 0) {
            const double curvature =
                (c.tangents[k + 1] - c.tangents[k - 1]).norm() / (c.arcLength[k + 1] - c.arcLength[k - 1]);
            EXPECT_LT(curvature * c.radius[k], kMaxBendRatio + 0.05) << "at sample " << i;
        }
    }
    // A Frenet frame would twist by the torsion, comparable to the turning;
    // the rotation-minimising frame twists by discretisation error only.
    EXPECT_LT(totalTwist, 0.02 * totalTurn) << "twist " << totalTwist << " rad, turn " << totalTurn << " rad";
}

TEST_P(ColonLayoutCase, AnatomyIsOnTheExpectedSides)
{
    const ColonLayout layout = layoutColon(withLengths(GetParam().lengths));
    const auto station = [&](Segment s) { return layout.stations[static_cast<std::size_t>(s)]; };
    EXPECT_GT(station(Segment::Descending).x(), 0.0) << "descending colon on the patient's left";
    EXPECT_GT(station(Segment::SplenicFlexure).x(), 0.0);
    EXPECT_LT(station(Segment::Ascending).x(), 0.0) << "ascending colon on the patient's right";
    EXPECT_LT(station(Segment::Cecum).x(), 0.0);
    EXPECT_GT(station(Segment::SplenicFlexure).z(), station(Segment::Sigmoid).z() + 0.1)
        << "splenic flexure high";
    // The rectum rises from the anus and bends posteriorly along the sacrum.
    const CentrelineSample mid = sampleCentreline(layout.centreline, 0.5 * layout.segmentStart[1]);
    EXPECT_GT(mid.point.y(), 0.0);
    EXPECT_GT(mid.point.z(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Population, ColonLayoutCase,
    ::testing::Values(LayoutCase{"typical", {0.15, 0.40, 0.25, 0.08, 0.48, 0.07, 0.17, 0.06}},
                      LayoutCase{"short110cm", {0.11, 0.25, 0.16, 0.05, 0.32, 0.05, 0.12, 0.04}},
                      LayoutCase{"redundant210cm", {0.16, 0.67, 0.25, 0.08, 0.66, 0.07, 0.17, 0.06}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ColonLayout, LongerTransverseSagsLower)
{
    AnatomyParameters shortTransverse;
    shortTransverse.transverseLength = 0.35;
    AnatomyParameters longTransverse;
    longTransverse.transverseLength = 0.70;
    const auto lowestTransverseZ = [](const ColonLayout& layout) {
        double z = 1e9;
        for (int i = 0; i < layout.centreline.numPoints(); ++i) {
            if (layout.centreline.segment[static_cast<std::size_t>(i)] == Segment::Transverse) {
                z = std::min(z, layout.centreline.points[static_cast<std::size_t>(i)].z());
            }
        }
        return z;
    };
    EXPECT_LT(lowestTransverseZ(layoutColon(longTransverse)),
              lowestTransverseZ(layoutColon(shortTransverse)) - 0.05);
}

}  // namespace
}  // namespace colonosim::geometry
