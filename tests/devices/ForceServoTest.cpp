// The HDC's force path: clamps, rate limit, non-finite refusal, watchdog,
// lost link and emergency stop, tick by tick at the servo period.
#include "simcore/devices/ForceServo.h"
#include "simcore/devices/TimeHistogram.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace colonosim::devices;

constexpr double kPeriod = 1e-3;

/// Ticks until time `until` (s), returning the largest step of the force.
double tickUntil(ForceServo& servo, double& now, double until)
{
    double largest = 0.0;
    while (now < until - 1e-12) {
        now += kPeriod;
        const double before = servo.output().force;
        largest = std::max(largest, std::abs(servo.tick(now).force - before));
    }
    return largest;
}

TEST(ForceServo, NoStepExceedsTheRateLimitAndTheClampHolds)
{
    ForceServo servo{HapticParameters{}};
    const double limit = servo.parameters().forceRateLimit * kPeriod;
    double now = 0.0;
    ASSERT_TRUE(servo.receive({40.0, 3.0}, now, now));  // beyond both device limits
    double largest = tickUntil(servo, now, 0.015);
    EXPECT_DOUBLE_EQ(servo.output().force, servo.parameters().maxForce);
    EXPECT_DOUBLE_EQ(servo.output().torque, servo.parameters().maxTorque);
    ASSERT_TRUE(servo.receive({-40.0, -3.0}, now, now));
    largest = std::max(largest, tickUntil(servo, now, 0.030));
    EXPECT_DOUBLE_EQ(servo.output().force, -servo.parameters().maxForce);
    EXPECT_LE(largest, limit + 1e-12);
    EXPECT_GT(largest, 0.9 * limit);  // the limit was reached, so it was what held the step
}

TEST(ForceServo, NonFiniteCommandsAreNeverApplied)
{
    ForceServo servo{HapticParameters{}};
    double now = 0.0;
    ASSERT_TRUE(servo.receive({5.0, 0.1}, now, now));
    tickUntil(servo, now, 0.01);
    ASSERT_TRUE(servo.receive({5.0, 0.1}, now, now));  // fresh, so the watchdog stays quiet
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(servo.receive({nan, 0.0}, now, now));
    EXPECT_FALSE(servo.receive({0.0, inf}, now, now));
    EXPECT_FALSE(servo.receive({1.0, 0.0}, nan, now));
    EXPECT_EQ(servo.rejectedCommands(), 3);
    for (int i = 0; i < 10; ++i) {
        now += kPeriod;
        const HandleCommand& out = servo.tick(now);
        ASSERT_TRUE(std::isfinite(out.force) && std::isfinite(out.torque));
        EXPECT_NEAR(out.force, 5.0, 1e-12);  // the last good command stays
    }
}

TEST(ForceServo, ALostLinkBringsFullForceToZeroWithinFiveMilliseconds)
{
    ForceServo servo{HapticParameters{}};
    double now = 0.0;
    ASSERT_TRUE(servo.receive({25.0, 1.0}, now, now));
    tickUntil(servo, now, 0.01);
    ASSERT_DOUBLE_EQ(servo.output().force, 25.0);
    servo.linkLost();
    const double lost = now;
    while (servo.output().force != 0.0 || servo.output().torque != 0.0) {
        now += kPeriod;
        servo.tick(now);
        ASSERT_LT(now - lost, 0.02) << "force never reached zero";
    }
    EXPECT_LE(now - lost, 5e-3 + 1e-12);
    EXPECT_EQ(servo.state(), ServoState::LinkLost);
}

TEST(ForceServo, ASilentSimulatorTripsTheWatchdog)
{
    ForceServo servo{HapticParameters{}};
    const double timeout = servo.parameters().watchdogTimeout;
    double now = 0.0;
    ASSERT_TRUE(servo.receive({10.0, 0.0}, now, now));
    tickUntil(servo, now, timeout - 2 * kPeriod);
    EXPECT_EQ(servo.state(), ServoState::Following);
    EXPECT_NEAR(servo.output().force, 10.0, 1e-12);
    tickUntil(servo, now, timeout + 2 * kPeriod);
    EXPECT_EQ(servo.state(), ServoState::Watchdog);
    tickUntil(servo, now, timeout + 8 * kPeriod);
    EXPECT_DOUBLE_EQ(servo.output().force, 0.0);
    // The simulator speaks again: the servo follows again.
    ASSERT_TRUE(servo.receive({4.0, 0.0}, now, now));
    tickUntil(servo, now, now + 5 * kPeriod);
    EXPECT_EQ(servo.state(), ServoState::Following);
    EXPECT_NEAR(servo.output().force, 4.0, 1e-9);
}

TEST(ForceServo, EmergencyStopZeroesAtOnceAndLatches)
{
    ForceServo servo{HapticParameters{}};
    double now = 0.0;
    ASSERT_TRUE(servo.receive({20.0, 0.5}, now, now));
    tickUntil(servo, now, 0.01);
    servo.emergencyStop();
    now += kPeriod;
    EXPECT_EQ(servo.tick(now).force, 0.0);
    servo.receive({20.0, 0.5}, now, now);
    tickUntil(servo, now, now + 0.01);
    EXPECT_EQ(servo.output().force, 0.0);
    EXPECT_EQ(servo.state(), ServoState::EmergencyStop);
    servo.reset();
    servo.receive({20.0, 0.5}, now, now);
    tickUntil(servo, now, now + 0.01);
    EXPECT_NEAR(servo.output().force, 20.0, 1e-9);
}

TEST(ForceServo, ExtrapolatesBetweenUpdatesWithinTheHorizon)
{
    const double horizon = HapticParameters{}.extrapolationHorizon;
    ForceServo fresh{HapticParameters{}};
    fresh.receive({0.0, 0.0}, 0.0, 0.0);
    fresh.receive({1.0, 0.0}, 1e-3, 1e-3);
    double t = 1e-3;
    double out = 0.0;
    for (int k = 0; k < 15; ++k) {  // 15 ms: past the horizon, inside the watchdog
        t += kPeriod;
        out = fresh.tick(t).force;
    }
    // Held at the last value plus the trend over the horizon, not beyond it.
    EXPECT_NEAR(out, 1.0 + horizon / 1e-3 * 1.0, 1e-9);
}

}  // namespace

namespace {

TEST(TimeHistogram, QuantilesToTheMicrosecondAndTheExactMaximum)
{
    colonosim::devices::TimeHistogram h;
    EXPECT_EQ(h.quantile(0.5), 0.0);
    for (int us = 1; us <= 1000; ++us) {
        h.add((us - 0.5) * 1e-6);  // one sample in each of the first 1,000 bins
    }
    EXPECT_EQ(h.count(), 1000);
    EXPECT_NEAR(h.quantile(0.5), 501e-6, 1e-12);
    EXPECT_NEAR(h.quantile(0.99), 991e-6, 1e-12);
    h.add(0.2);  // beyond the last bin: counted, and the maximum is exact
    EXPECT_DOUBLE_EQ(h.max(), 0.2);
    EXPECT_DOUBLE_EQ(h.quantile(1.0), 0.2);
    EXPECT_NEAR(h.quantile(0.5), 501e-6, 1e-12);
}

TEST(TimeHistogram, TheShareAboveADurationCountsTheBinsWhollyAboveIt)
{
    colonosim::devices::TimeHistogram h;
    EXPECT_EQ(h.fractionAbove(1e-3), 0.0) << "empty";
    // Latencies as a 1 kHz servo sees them: whole ticks with a little jitter.
    for (int k = 0; k < 97; ++k) {
        h.add(1.0004e-3);
    }
    h.add(1.98e-3);
    h.add(2.001e-3);
    h.add(0.06);  // beyond the last bin: still counted above
    EXPECT_NEAR(h.fractionAbove(1.5e-3), 0.03, 1e-12);
    EXPECT_NEAR(h.fractionAbove(0.5e-3), 1.0, 1e-12);
    EXPECT_NEAR(h.fractionAbove(0.05), 0.01, 1e-12);
    EXPECT_EQ(h.fractionAbove(0.1), 0.0) << "nothing is longer than the maximum";
}

}  // namespace
