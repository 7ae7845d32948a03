#include "case_generator/Random.h"

#include "case_generator/DeterministicMath.h"

namespace colonosim::cases {

namespace {
constexpr std::uint64_t rotl(std::uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}
}  // namespace

std::uint64_t splitMix64(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

Random::Random(std::uint64_t seed, std::uint64_t attempt)
{
    std::uint64_t mix = attempt;
    std::uint64_t state = seed ^ splitMix64(mix);
    for (std::uint64_t& word : m_s) {
        word = splitMix64(state);
    }
}

Random Random::fromState(const std::array<std::uint64_t, 4>& state)
{
    Random random;
    random.m_s = state;
    return random;
}

std::uint64_t Random::next()
{
    const std::uint64_t result = rotl(m_s[1] * 5, 7) * 9;
    const std::uint64_t t = m_s[1] << 17;
    m_s[2] ^= m_s[0];
    m_s[3] ^= m_s[1];
    m_s[1] ^= m_s[2];
    m_s[0] ^= m_s[3];
    m_s[2] ^= t;
    m_s[3] = rotl(m_s[3], 45);
    return result;
}

double Random::uniform()
{
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

std::uint64_t Random::below(std::uint64_t n)
{
    if (n <= 1) {
        return 0;
    }
    const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n
    for (;;) {
        const std::uint64_t x = next();
        const unsigned __int128 product = static_cast<unsigned __int128>(x) * n;
        if (static_cast<std::uint64_t>(product) >= threshold) {
            return static_cast<std::uint64_t>(product >> 64);
        }
    }
}

int Random::integer(int lo, int hi)
{
    return lo + static_cast<int>(below(static_cast<std::uint64_t>(hi - lo) + 1));
}

double Random::normal(double mean, double sd)
{
    double u = uniform();
    while (u == 0.0) {
        u = uniform();
    }
    return mean + sd * detmath::normalQuantile(u);
}

std::size_t Random::choose(std::span<const double> weights)
{
    double total = 0.0;
    for (const double w : weights) {
        total += w;
    }
    const double target = uniform() * total;
    double running = 0.0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        running += weights[i];
        if (target < running) {
            return i;
        }
    }
    // Only reached through rounding at the top end: the last non-zero weight.
    for (std::size_t i = weights.size(); i-- > 0;) {
        if (weights[i] > 0.0) {
            return i;
        }
    }
    return 0;
}

}  // namespace colonosim::cases
