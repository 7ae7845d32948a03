// The endoscope view's dynamic resolution, on frame times it is given: it
// stays at full size while the rate holds, steps down while slow draws hold
// the rate back, not when something else does, comes back up once a larger
// picture would keep the rate, and starts its judgement again after a pause.
#include "trainer_ui/app/RenderScaleGovernor.h"

#include <gtest/gtest.h>

namespace {

using colonosim::app::RenderScaleGovernor;

/// Feeds `seconds` of frames every `interval` s, each drawing for
/// `drawAtFull` s times the scale's pixel share plus `fixed` s; returns the
/// time after the last frame.
double feed(RenderScaleGovernor& governor, double from, double seconds, double interval, double drawAtFull,
            double fixed = 0.0)
{
    double t = from;
    for (; t < from + seconds; t += interval) {
        const double s = governor.scale();
        governor.frameDrawn(t, fixed + drawAtFull * s * s);
    }
    return t;
}

/// The frames a draw of `drawAtFull * s^2 + fixed` and `other` s of other work allow at the present scale.
double frameInterval(const RenderScaleGovernor& governor, double drawAtFull, double fixed, double other)
{
    const double s = governor.scale();
    return fixed + drawAtFull * s * s + other;
}

TEST(RenderScaleGovernor, AViewThatKeepsItsRateStaysAtFullSize)
{
    RenderScaleGovernor governor;
    feed(governor, 0.0, 10.0, 1.0 / 33.0, 0.024);
    EXPECT_EQ(governor.scale(), 1.0);
    EXPECT_EQ(governor.changes(), 0);
}

TEST(RenderScaleGovernor, SlowDrawsStepTheScaleDownUntilTheRateHolds)
{
    RenderScaleGovernor governor;
    // A draw of 6 ms plus 50 ms of pixels at full size, 4 ms of other work:
    // 17 frames/s at full size, 30 or more at 0.64 (6 + 20.5 + 4 = 30.5 ms -> 32.8/s).
    constexpr double kPixels = 0.050;
    constexpr double kFixed = 0.006;
    constexpr double kOther = 0.004;
    double t = 0.0;
    for (int k = 0; k < 400; ++k) {
        const double interval = frameInterval(governor, kPixels, kFixed, kOther);
        governor.frameDrawn(t, interval - kOther);
        t += interval;
    }
    EXPECT_EQ(governor.scale(), 0.64);
    EXPECT_EQ(governor.changes(), 2) << "down twice, and no back and forth";
    EXPECT_GE(1.0 / frameInterval(governor, kPixels, kFixed, kOther), RenderScaleGovernor::kTargetRate);
}

TEST(RenderScaleGovernor, ASlowRateThatTheDrawDoesNotCauseKeepsTheScale)
{
    // 15 frames/s with a 10 ms draw: the rest of the window holds it back,
    // and a smaller picture would not help.
    RenderScaleGovernor governor;
    feed(governor, 0.0, 10.0, 1.0 / 15.0, 0.010);
    EXPECT_EQ(governor.scale(), 1.0);
}

TEST(RenderScaleGovernor, TheScaleStopsAtItsLeast)
{
    RenderScaleGovernor governor;
    double t = 0.0;
    for (int k = 0; k < 600; ++k) {
        governor.frameDrawn(t, 0.2);  // 5 frames/s whatever the scale
        t += 0.2;
    }
    EXPECT_EQ(governor.scale(), RenderScaleGovernor::kScales.back());
}

TEST(RenderScaleGovernor, ItComesBackUpOnceALargerPictureKeepsTheRate)
{
    RenderScaleGovernor governor;
    double t = feed(governor, 0.0, 6.0, 1.0 / 12.0, 1.0 / 12.0);  // drawing all the time at 12 frames/s
    ASSERT_LT(governor.scale(), 1.0);
    // The loop catches up: a full-size draw now takes 14 ms and a frame 20 ms.
    for (int k = 0; k < 600; ++k) {
        const double s = governor.scale();
        const double draw = 0.014 * s * s;
        governor.frameDrawn(t, draw);
        t += draw + 0.006;
    }
    EXPECT_EQ(governor.scale(), 1.0);
}

TEST(RenderScaleGovernor, APauseStartsTheJudgementAgain)
{
    // 30 frames/s with 30 ms draws for 0.4 s, a pause of 0.3 s (a paused
    // procedure draws nothing), then on as before: counted over the pause,
    // 14 frames in 0.7 s would read as 19 frames/s held back by the draw.
    RenderScaleGovernor governor;
    const double t = feed(governor, 0.0, 0.4, 1.0 / 30.0, 0.030);
    feed(governor, t + 0.3, 2.0, 1.0 / 30.0, 0.030);
    EXPECT_EQ(governor.scale(), 1.0);
    EXPECT_EQ(governor.changes(), 0);
}

}  // namespace
