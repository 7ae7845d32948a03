// The specified generator and our own sampling: reference outputs of
// xoshiro256** and SplitMix64, and the laws of the sampling routines.

#include "case_generator/Random.h"
#include "case_generator/DeterministicMath.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::cases {

TEST(Random, Xoshiro256StarStarMatchesTheReferenceOutputs)
{
    // Reference implementation (Blackman & Vigna) from the state {1, 2, 3, 4}.
    Random random = Random::fromState({1, 2, 3, 4});
    EXPECT_EQ(random.next(), 11520u);
    EXPECT_EQ(random.next(), 0u);
    EXPECT_EQ(random.next(), 1509978240u);
    EXPECT_EQ(random.next(), 1215971899390074240u);
}

TEST(Random, SplitMix64MatchesTheReferenceOutputs)
{
    std::uint64_t state = 1234567;
    EXPECT_EQ(splitMix64(state), 6457827717110365317u);
    EXPECT_EQ(splitMix64(state), 3203168211198807973u);
    EXPECT_EQ(splitMix64(state), 9817491932198370423u);
}

TEST(Random, StreamsDependOnSeedAndAttempt)
{
    Random a(42, 0);
    Random b(42, 0);
    Random c(42, 1);
    Random d(43, 0);
    const std::uint64_t first = a.next();
    EXPECT_EQ(first, b.next());
    EXPECT_NE(first, c.next());
    EXPECT_NE(first, d.next());
}

TEST(Random, UniformBelowAndChooseStayInRange)
{
    Random random(7, 0);
    const std::array<double, 4> weights{0.0, 1.0, 0.0, 3.0};
    std::array<int, 4> counts{};
    for (int i = 0; i < 100000; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        ASSERT_LT(random.below(7), 7u);
        const int k = random.integer(-2, 2);
        ASSERT_GE(k, -2);
        ASSERT_LE(k, 2);
        ++counts[random.choose(weights)];
    }
    EXPECT_EQ(counts[0], 0);
    EXPECT_EQ(counts[2], 0);
    // Share of index 3 is 0.75; binomial SE 0.0014, bound 4.5 SE.
    EXPECT_NEAR(counts[3] / 100000.0, 0.75, 4.5 * std::sqrt(0.75 * 0.25 / 100000));
}

TEST(Random, NormalHasItsMeanAndSd)
{
    Random random(11, 0);
    constexpr int n = 200000;
    double sum = 0.0;
    double squares = 0.0;
    for (int i = 0; i < n; ++i) {
        const double x = random.normal(3.0, 2.0);
        sum += x;
        squares += x * x;
    }
    const double mean = sum / n;
    const double sd = std::sqrt(squares / n - mean * mean);
    // SE of the mean 2 / sqrt(n) = 0.0045; of the SD about 2 / sqrt(2n) = 0.0032; bound 4.5 SE.
    EXPECT_NEAR(mean, 3.0, 4.5 * 2.0 / std::sqrt(n));
    EXPECT_NEAR(sd, 2.0, 4.5 * 2.0 / std::sqrt(2.0 * n));
}

TEST(DeterministicMath, ExpAndLogAgreeWithLibmToRoundingError)
{
    for (double x = -30.0; x <= 30.0; x += 0.0137) {
        EXPECT_NEAR(detmath::exp(x), std::exp(x), 4e-15 * std::exp(x)) << x;
    }
    for (double x = 1e-6; x < 1e6; x *= 1.37) {
        EXPECT_NEAR(detmath::log(x), std::log(x), 4e-15 * std::max(1.0, std::abs(std::log(x)))) << x;
    }
    EXPECT_TRUE(std::isnan(detmath::log(-1.0)));
}

TEST(DeterministicMath, NormalQuantileMatchesTables)
{
    // Acklam's approximation: relative error below 1.15e-9.
    EXPECT_NEAR(detmath::normalQuantile(0.975), 1.959963984540054, 3e-9);
    EXPECT_NEAR(detmath::normalQuantile(0.5), 0.0, 1e-15);
    EXPECT_NEAR(detmath::normalQuantile(0.001), -3.090232306167813, 4e-9);
    EXPECT_NEAR(detmath::normalQuantile(0.9999), 3.719016485455709, 5e-9);
    EXPECT_TRUE(std::isnan(detmath::normalQuantile(1.0)));
}

}  // namespace colonosim::cases
