// The procedure loop's pacing on a virtual clock: a loop that keeps up runs
// at real time (times the speed), a short lag is made up, and a long one is
// dropped, so that cheap steps after slow ones do not run faster than the
// hands.
#include "trainer_ui/cli/LoopPacer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace {

using colonosim::cli::LoopPacer;

constexpr double kDt = 0.001;  ///< s: the loop's step

/// A loop on a virtual clock: each step costs `cost(simTime)` s of wall time
/// and the loop sleeps until a step is due, as SimulationRunner does.
struct VirtualLoop {
    LoopPacer pacer;
    double sim = 0.0;   ///< s simulated
    double wall = 0.0;  ///< s on the wall clock

    explicit VirtualLoop(double speed = 1.0) { pacer.restart(sim, wall, speed); }

    /// Runs until the wall clock reaches `until`; returns the most simulated
    /// time gained over any `window` s of wall time.
    double runUntil(double until, const std::function<double(double)>& cost, double window = 0.5)
    {
        double windowStart = wall;
        double simAtStart = sim;
        double most = 0.0;
        while (wall < until) {
            const double due = pacer.dueAt(sim, kDt, wall);
            if (due > wall) {
                wall = due;  // sleeps until the step is due
            } else {
                wall += cost(sim);
                sim += kDt;
            }
            if (wall - windowStart >= window) {
                most = std::max(most, sim - simAtStart);
                windowStart = wall;
                simAtStart = sim;
            }
        }
        return most;
    }
};

TEST(LoopPacer, ALoopThatKeepsUpRunsAtRealTime)
{
    VirtualLoop loop;
    loop.runUntil(10.0, [](double) { return 0.0004; });
    EXPECT_NEAR(loop.sim, 10.0, 2.0 * kDt);
    EXPECT_EQ(loop.pacer.dropped(), 0.0);
}

TEST(LoopPacer, FollowsTheAskedSpeed)
{
    VirtualLoop loop(4.0);
    loop.runUntil(2.0, [](double) { return 0.0001; });
    EXPECT_NEAR(loop.sim, 8.0, 2.0 * kDt);
}

TEST(LoopPacer, AShortLagIsMadeUp)
{
    // A thread scheduled 50 ms late: the steps then run back to back until
    // the loop is on time again, and none of the lag is dropped.
    VirtualLoop loop;
    loop.runUntil(1.0, [](double) { return 0.0002; });
    loop.wall += 0.05;
    loop.runUntil(2.0, [](double) { return 0.0002; });
    EXPECT_NEAR(loop.sim, 2.0, 2.0 * kDt);
    EXPECT_EQ(loop.pacer.dropped(), 0.0);
}

TEST(LoopPacer, CheapStepsAfterSlowOnesDoNotOutrunRealTime)
{
    // 10 s of steps that take 1.6 ms (the loop at 62% of real time, as deep
    // in the colon), then steps of 0.2 ms (the colon asleep on the way out).
    VirtualLoop loop;
    loop.runUntil(10.0, [](double) { return 0.0016; });
    EXPECT_NEAR(loop.sim, 10.0 / 1.6, 0.01) << "behind, the steps run back to back";
    EXPECT_GT(loop.pacer.dropped(), 3.0) << "the lag beyond kMaxLag is dropped as it grows";
    const double simBefore = loop.sim;
    const double most = loop.runUntil(20.0, [](double) { return 0.0002; });
    // Once cheap, the loop makes up at most kMaxLag and then keeps real time:
    // no half second of wall time carries more than half a second and the
    // kept lag of simulated time. Without the drop it runs five times faster
    // than real time until it has made up the 3.75 s it lost (2.5 s of
    // simulated time in a half second of wall time).
    EXPECT_LE(most, 0.5 + LoopPacer::kMaxLag + 2.0 * kDt);
    EXPECT_NEAR(loop.sim - simBefore, 10.0 + LoopPacer::kMaxLag, 2.0 * kDt);
}

}  // namespace
