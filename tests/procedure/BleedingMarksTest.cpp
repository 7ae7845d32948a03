// Contact bleeding marks from wall loads: a mark needs a force above the
// threshold held for the minimum time at one place; a repeat within a mark's
// radius strengthens it; the cap holds; bad parameters are refused by name;
// the same loads give the same marks.

#include "simcore/procedure/BleedingMarks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace colonosim;
using procedure::BleedingMarks;
using procedure::BleedingParameters;
using procedure::WallLoad;

constexpr double kStep = 1e-3;  // s, the loop step

/// Holds `loads` for `steps` loop steps starting at `time`; returns the
/// number of marks that appeared.
int hold(BleedingMarks& marks, const std::vector<WallLoad>& loads, int steps, double& time)
{
    int appeared = 0;
    for (int s = 0; s < steps; ++s) {
        time += kStep;
        appeared += marks.update(loads, kStep, time);
    }
    return appeared;
}

TEST(BleedingMarks, ASustainedLoadAboveThresholdMakesOneMarkAtItsPlace)
{
    const BleedingParameters p;
    BleedingMarks marks(p);
    const Eigen::Vector3d place(0.01, 0.02, 0.03);
    double time = 0.0;
    const int steps = static_cast<int>(p.minDuration / kStep) + 20;
    EXPECT_EQ(hold(marks, {{place, 1.5 * p.forceThreshold}}, steps, time), 1);
    ASSERT_EQ(marks.marks().size(), 1U);
    const procedure::ContactMark& mark = marks.marks().front();
    EXPECT_EQ(mark.restPoint, place);
    EXPECT_NEAR(mark.onset, p.minDuration, 1.5 * kStep) << "appears once the minimum time has passed";
    EXPECT_GT(mark.radius, p.minRadius);
    EXPECT_LT(mark.radius, p.maxRadius);
    EXPECT_DOUBLE_EQ(mark.radius, marks.radiusFor(1.5 * p.forceThreshold));
}

TEST(BleedingMarks, BelowThresholdOrTooShortMakesNone)
{
    const BleedingParameters p;
    const Eigen::Vector3d place(0.0, 0.0, 0.05);
    const int longEnough = static_cast<int>(2.0 * p.minDuration / kStep);
    const int tooShort = static_cast<int>(0.8 * p.minDuration / kStep);
    BleedingMarks gentle(p);
    double time = 0.0;
    EXPECT_EQ(hold(gentle, {{place, 0.95 * p.forceThreshold}}, longEnough, time), 0);
    BleedingMarks brief(p);
    // Short presses separated by a release: the pressure must be continuous.
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(hold(brief, {{place, 3.0 * p.forceThreshold}}, tooShort, time), 0);
        EXPECT_EQ(hold(brief, {}, static_cast<int>(2.0 * p.releaseTime / kStep), time), 0);
    }
    EXPECT_TRUE(gentle.marks().empty());
    EXPECT_TRUE(brief.marks().empty());
}

TEST(BleedingMarks, ASecondPressWithinTheRadiusStrengthensInsteadOfAdding)
{
    const BleedingParameters p;
    BleedingMarks marks(p);
    double time = 0.0;
    const int steps = static_cast<int>(p.minDuration / kStep) + 5;
    const Eigen::Vector3d first(0.0, 0.0, 0.1);
    ASSERT_EQ(hold(marks, {{first, p.forceThreshold}}, steps, time), 1);
    const double opacity = marks.marks().front().opacity;
    const double radius = marks.marks().front().radius;
    hold(marks, {}, 100, time);  // released
    const Eigen::Vector3d near = first + Eigen::Vector3d(0.5 * radius, 0.0, 0.0);
    EXPECT_EQ(hold(marks, {{near, p.saturationForce}}, steps, time), 0);
    ASSERT_EQ(marks.marks().size(), 1U);
    EXPECT_GT(marks.marks().front().opacity, opacity);
    EXPECT_DOUBLE_EQ(marks.marks().front().radius, p.maxRadius) << "grown to the harder press's size";
    hold(marks, {}, 100, time);
    const Eigen::Vector3d far = first + Eigen::Vector3d(0.0, 3.0 * p.maxRadius, 0.0);
    EXPECT_EQ(hold(marks, {{far, p.forceThreshold}}, steps, time), 1);
    EXPECT_EQ(marks.marks().size(), 2U);
}

TEST(BleedingMarks, TheCapHoldsAndStrengthensTheNearest)
{
    const BleedingParameters p;
    BleedingMarks marks(p);
    double time = 0.0;
    const int steps = static_cast<int>(p.minDuration / kStep) + 2;
    const double spacing = 4.0 * p.maxRadius;
    for (int k = 0; k < BleedingMarks::kMaxMarks + 10; ++k) {
        hold(marks, {{Eigen::Vector3d(spacing * k, 0.0, 0.0), p.forceThreshold}}, steps, time);
        hold(marks, {}, 100, time);
    }
    ASSERT_EQ(static_cast<int>(marks.marks().size()), BleedingMarks::kMaxMarks);
    // The ten presses beyond the cap all went to the last mark, the nearest.
    EXPECT_DOUBLE_EQ(marks.marks().back().opacity, 1.0);
    EXPECT_DOUBLE_EQ(marks.marks().front().opacity, 0.6);
}

TEST(BleedingMarks, TheSameLoadsGiveTheSameMarks)
{
    const BleedingParameters p;
    BleedingMarks a(p);
    BleedingMarks b(p);
    for (int s = 0; s < 3000; ++s) {
        // A press that wanders over the wall with a varying force.
        const double force = p.forceThreshold * (1.0 + 0.9 * std::sin(0.004 * s));
        const std::vector<WallLoad> loads{
            {Eigen::Vector3d(3e-6 * s, 2e-3 * std::cos(0.003 * s), 0.0), force}};
        EXPECT_EQ(a.update(loads, kStep, s * kStep), b.update(loads, kStep, s * kStep));
    }
    ASSERT_EQ(a.marks().size(), b.marks().size());
    ASSERT_FALSE(a.marks().empty());
    for (size_t k = 0; k < a.marks().size(); ++k) {
        EXPECT_EQ(a.marks()[k].restPoint, b.marks()[k].restPoint);
        EXPECT_EQ(a.marks()[k].radius, b.marks()[k].radius);
        EXPECT_EQ(a.marks()[k].opacity, b.marks()[k].opacity);
        EXPECT_EQ(a.marks()[k].onset, b.marks()[k].onset);
    }
}

struct InvalidCase {
    const char* field;
    void (*spoil)(BleedingParameters&);
};

class BleedingParametersInvalid : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(BleedingParametersInvalid, AreRefusedNamingTheField)
{
    BleedingParameters p;
    GetParam().spoil(p);
    try {
        BleedingMarks marks(p);
        FAIL() << "accepted an invalid " << GetParam().field;
    } catch (const params::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find(GetParam().field), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Fields, BleedingParametersInvalid,
    ::testing::Values(InvalidCase{"forceThreshold", [](BleedingParameters& p) { p.forceThreshold = -1.0; }},
                      InvalidCase{"minDuration", [](BleedingParameters& p) { p.minDuration = 20.0; }},
                      InvalidCase{"saturationForce", [](BleedingParameters& p) { p.saturationForce = 1e3; }},
                      InvalidCase{"saturationForce", [](BleedingParameters& p) { p.saturationForce = 0.5; }},
                      InvalidCase{"minRadius", [](BleedingParameters& p) { p.minRadius = 0.0; }},
                      InvalidCase{"maxRadius", [](BleedingParameters& p) { p.maxRadius = 0.8e-3; }},
                      InvalidCase{"releaseTime", [](BleedingParameters& p) { p.releaseTime = -0.01; }},
                      InvalidCase{"forceThreshold",
                                  [](BleedingParameters& p) { p.forceThreshold = std::nan(""); }}));

}  // namespace
