/// \file
/// The laid-out centreline has no kink tighter than its lumen: the bend
/// radius is at least twice the declared lumen radius everywhere, so the
/// lumen is never narrowed by bend limiting by more than 20 %.

#include "simcore/geometry/ColonLayout.h"

#include "simcore/geometry/CentrelineSampling.h"

#include "SegmentLengths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>

namespace colonosim::geometry {
namespace {

struct BendCase {
    const char* name;
    std::array<double, kNumSegments> lengths;  // m, rectum -> cecum
};

void PrintTo(const BendCase& c, std::ostream* os)
{
    *os << c.name;
}

using testing::withLengths;

constexpr double kStencil = 0.003;  ///< tangents compared +-3 mm apart
constexpr double kWindow = 0.005;   ///< curvature averaged over +-5 mm

/// Curvature at arc length s: the tangent turn over +-kStencil.
double rawCurvature(const Centreline& c, double s)
{
    const double a = std::max(0.0, s - kStencil);
    const double b = std::min(c.length(), s + kStencil);
    const Eigen::Vector3d ta = sampleCentreline(c, a).tangent;
    const Eigen::Vector3d tb = sampleCentreline(c, b).tangent;
    return std::acos(std::clamp(ta.dot(tb), -1.0, 1.0)) / (b - a);
}

/// Curvature averaged over +-kWindow (1 mm steps) around s.
double smoothedCurvature(const Centreline& c, double s)
{
    double sum = 0.0;
    int count = 0;
    for (double x = s - kWindow; x <= s + kWindow + 1e-12; x += 0.001) {
        if (x < kStencil || x > c.length() - kStencil)
            continue;
        sum += rawCurvature(c, x);
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

/// Smallest declared radius among the segments within the +-3 cm blend of s.
double smallestDeclaredNear(const ColonLayout& layout, const AnatomyParameters& p, double s)
{
    double r = 1e9;
    for (int seg = 0; seg < kNumSegments; ++seg) {
        const auto k = static_cast<std::size_t>(seg);
        if (s >= layout.segmentStart[k] - 0.03 && s <= layout.segmentStart[k + 1] + 0.03) {
            r = std::min(r, 0.5 * p.diameter(static_cast<Segment>(seg)));
        }
    }
    return r;
}

class ColonBendCase : public ::testing::TestWithParam<BendCase> {};

TEST_P(ColonBendCase, BendRadiusIsAtLeastTwiceTheDeclaredLumenRadius)
{
    const AnatomyParameters p = withLengths(GetParam().lengths);
    const ColonLayout layout = layoutColon(p);
    const Centreline& c = layout.centreline;
    // Per segment: the smallest bend radius / declared lumen radius, and where.
    std::array<double, kNumSegments> worst{};
    worst.fill(1e9);
    std::array<double, kNumSegments> worstS{};
    for (int i = 0; i < c.numPoints(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const double kappa = smoothedCurvature(c, c.arcLength[k]);
        const double ratio = kappa > 0.0 ? 1.0 / (kappa * 0.5 * p.diameter(c.segment[k])) : 1e9;
        const auto seg = static_cast<std::size_t>(c.segment[k]);
        if (ratio < worst[seg]) {
            worst[seg] = ratio;
            worstS[seg] = c.arcLength[k];
        }
    }
    for (int seg = 0; seg < kNumSegments; ++seg) {
        const auto k = static_cast<std::size_t>(seg);
        const double declared = 0.5 * p.diameter(static_cast<Segment>(seg));
        std::cout << GetParam().name << " " << segmentName(static_cast<Segment>(seg)) << ": min bend radius "
                  << 1e3 * worst[k] * declared << " mm at s = " << worstS[k] << " m (declared lumen radius "
                  << 1e3 * declared << " mm)\n";
        EXPECT_GE(worst[k], kMinBendRadiusRatio)
            << segmentName(static_cast<Segment>(seg)) << " at s = " << worstS[k] << " m";
    }
}

TEST_P(ColonBendCase, BendLimitingNarrowsTheLumenByAtMost20Percent)
{
    const AnatomyParameters p = withLengths(GetParam().lengths);
    const ColonLayout layout = layoutColon(p);
    const Centreline& c = layout.centreline;
    // Per segment: the smallest lumen radius / allowed radius, and where.
    std::array<double, kNumSegments> minRadius{};
    minRadius.fill(1e9);
    std::array<double, kNumSegments> worst{};
    worst.fill(1e9);
    std::array<double, kNumSegments> worstS{};
    for (int i = 0; i < c.numPoints(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        const auto seg = static_cast<std::size_t>(c.segment[k]);
        minRadius[seg] = std::min(minRadius[seg], c.radius[k]);
        const double ratio = c.radius[k] / (0.8 * smallestDeclaredNear(layout, p, c.arcLength[k]));
        if (ratio < worst[seg]) {
            worst[seg] = ratio;
            worstS[seg] = c.arcLength[k];
        }
    }
    for (int seg = 0; seg < kNumSegments; ++seg) {
        const auto k = static_cast<std::size_t>(seg);
        std::cout << GetParam().name << " " << segmentName(static_cast<Segment>(seg)) << ": min lumen radius "
                  << 1e3 * minRadius[k] << " mm (declared " << 0.5e3 * p.diameter(static_cast<Segment>(seg))
                  << " mm)\n";
        EXPECT_GE(worst[k], 1.0) << segmentName(static_cast<Segment>(seg))
                                 << " narrowed below 80 % at s = " << worstS[k] << " m";
    }
}

INSTANTIATE_TEST_SUITE_P(
    Population, ColonBendCase,
    ::testing::Values(BendCase{"typical", {0.15, 0.40, 0.25, 0.08, 0.48, 0.07, 0.17, 0.06}},
                      BendCase{"short110cm", {0.11, 0.25, 0.16, 0.05, 0.32, 0.05, 0.12, 0.04}},
                      BendCase{"redundant210cm", {0.16, 0.67, 0.25, 0.08, 0.66, 0.07, 0.17, 0.06}}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace colonosim::geometry
