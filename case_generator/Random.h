#pragma once
/// \file
/// The case generator's random numbers: a specified generator and our own
/// sampling, so that a seed gives the same case on every machine (the
/// standard library's distributions differ between implementations).
///
/// - Generator: xoshiro256** 1.0 (Blackman & Vigna 2018), its state seeded
///   from SplitMix64 of the 64-bit case seed mixed with the attempt number.
/// - uniform(): the top 53 bits times 2^-53, in [0, 1), exact.
/// - below(n): an integer in [0, n) by rejection of the biased tail (Lemire).
/// - normal(): the inverse CDF of one uniform (detmath::normalQuantile), so
///   every draw consumes exactly one 64-bit output.
/// - choose(weights): the first index whose running sum exceeds u times the
///   total; sums in index order, so the result is fixed by the weights.

#include <array>
#include <cstdint>
#include <span>

namespace colonosim::cases {

class Random {
public:
    /// The stream for attempt `attempt` of the case with seed `seed`.
    Random(std::uint64_t seed, std::uint64_t attempt);
    /// A generator with the given xoshiro256** state (not all zero), for the reference tests.
    [[nodiscard]] static Random fromState(const std::array<std::uint64_t, 4>& state);

    [[nodiscard]] std::uint64_t next();
    [[nodiscard]] double uniform();
    [[nodiscard]] double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    [[nodiscard]] std::uint64_t below(std::uint64_t n);
    /// An integer in [lo, hi], both included.
    [[nodiscard]] int integer(int lo, int hi);
    [[nodiscard]] bool chance(double p) { return uniform() < p; }
    [[nodiscard]] double normal(double mean, double sd);
    [[nodiscard]] std::size_t choose(std::span<const double> weights);

private:
    Random() = default;
    std::array<std::uint64_t, 4> m_s{};
};

/// SplitMix64's output function (Steele, Lea & Flood 2014).
[[nodiscard]] std::uint64_t splitMix64(std::uint64_t& state);

}  // namespace colonosim::cases
