// The residual fluid's level (ResidualFluid.h) against closed forms.

#include "RenderScenes.h"

#include "simcore/render/ResidualFluid.h"
#include "simcore/render/WallSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

namespace {

using namespace colonosim;

constexpr double kRadius = 0.02;  // m
constexpr double kLength = 0.30;  // m

TEST(ResidualFluid, CircularSegmentAreaMatchesItsClosedForms)
{
    // Tolerance: the formula is exact; 1e-12 m^2 is rounding.
    EXPECT_NEAR(render::circularSegmentArea(kRadius, 0.0), 0.0, 1e-12);
    EXPECT_NEAR(render::circularSegmentArea(kRadius, kRadius), std::numbers::pi * kRadius * kRadius / 2.0,
                1e-12);
    EXPECT_NEAR(render::circularSegmentArea(kRadius, 2.0 * kRadius), std::numbers::pi * kRadius * kRadius,
                1e-12);
    EXPECT_NEAR(render::circularSegmentArea(kRadius, 5.0 * kRadius), std::numbers::pi * kRadius * kRadius,
                1e-12);
    // Shallow: A ~ (4/3) sqrt(2 r) d^(3/2) for d << r (within 1% at d = r / 1000).
    const double d = kRadius / 1000.0;
    EXPECT_NEAR(render::circularSegmentArea(kRadius, d) /
                    (4.0 / 3.0 * std::sqrt(2.0 * kRadius) * std::pow(d, 1.5)),
                1.0, 0.01);
}

struct LevelCase {
    double depth;  ///< m, of the pool in a horizontal tube
};

void PrintTo(const LevelCase& c, std::ostream* out)
{
    *out << c.depth << " m";
}

class HorizontalTubeLevel : public ::testing::TestWithParam<LevelCase> {};

// A horizontal straight tube holding V = A(r, h) L: the level is h above the
// tube's bottom, and the vertices below it are submerged by the height they
// lie below it.
TEST_P(HorizontalTubeLevel, IsTheDepthWhoseSegmentHoldsTheVolume)
{
    const double h = GetParam().depth;
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    const render::FluidPool pool{{geometry::Segment::Descending},
                                 render::circularSegmentArea(kRadius, h) * kLength};
    // Tolerance: the bisection is exact to rounding; the ring lengths sum to
    // the tube's length exactly (half-spacing at both ends), so 1e-9 m.
    EXPECT_NEAR(render::poolLevel(centreline, pool, up), -kRadius + h, 1e-9);

    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    render::WallFindings findings;
    findings.down = -up;
    findings.fluid.push_back(pool);
    const render::WallSurface surface = render::buildWallSurface(tube, centreline, findings);
    for (int i = 0; i < tube.numVertices(); ++i) {
        const double expected = -kRadius + h - tube.vertices(1, i);
        ASSERT_NEAR(surface.fluidDepth[static_cast<size_t>(i)], expected, 1e-6);  // float storage
    }
}

INSTANTIATE_TEST_SUITE_P(Depths, HorizontalTubeLevel,
                         ::testing::Values(LevelCase{0.002}, LevelCase{0.01}, LevelCase{0.02},
                                           LevelCase{0.035}),
                         [](const ::testing::TestParamInfo<LevelCase>& info) {
                             return std::to_string(std::lround(info.param.depth * 1000.0)) + "mm";
                         });

TEST(ResidualFluid, PoolsInTheLowestPartAndStaysInItsSegments)
{
    // A tube tilted 10 degrees (its far end higher): a small pool lies at the
    // low end only, with one level, and a stretch in another segment stays dry.
    auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const double tilt = 10.0 * std::numbers::pi / 180.0;
    const Eigen::Vector3d up(0.0, std::cos(tilt), std::sin(tilt));  // the far end (z = L) is higher
    for (size_t k = 0; k < centreline.segment.size(); ++k) {
        if (centreline.arcLength[k] > 0.25) {
            centreline.segment[k] = geometry::Segment::Sigmoid;
        }
    }
    const render::FluidPool pool{{geometry::Segment::Descending}, 5e-6};  // 5 mL
    const double level = render::poolLevel(centreline, pool, up);
    ASSERT_TRUE(std::isfinite(level));
    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    render::WallFindings findings;
    findings.down = -up;
    findings.fluid.push_back(pool);
    const render::WallSurface surface = render::buildWallSurface(tube, centreline, findings);
    double wetNear = 0.0;
    double wetFar = 0.0;
    for (int i = 0; i < tube.numVertices(); ++i) {
        const double depth = surface.fluidDepth[static_cast<size_t>(i)];
        const double z = tube.vertices(2, i);
        if (z > 0.2505) {
            EXPECT_EQ(depth, render::kDryDepth) << "z " << z;
        } else if (z < 0.2495) {
            ASSERT_NEAR(depth, level - tube.vertices.col(i).dot(up), 1e-6);
        }
        (z < 0.1 ? wetNear : wetFar) += depth > 0.0 ? 1.0 : 0.0;
    }
    EXPECT_GT(wetNear, 0.0);
    EXPECT_EQ(wetFar, 0.0) << "5 mL in a tube tilted 10 degrees stays within its lowest 10 cm";
    // Empty pool: no level.
    EXPECT_TRUE(std::isnan(render::poolLevel(centreline, {{geometry::Segment::Descending}, 0.0}, up)));
}

}  // namespace
