#pragma once
/// \file
/// Durations counted in 1 us bins up to 50 ms (beyond: an overflow bin), with
/// the exact maximum: quantiles of a servo's periods or latencies over any
/// length of run in fixed memory (400 kB, taken once), without allocating in
/// the loop that adds.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace colonosim::devices {

class TimeHistogram {
public:
    static constexpr double kBin = 1e-6;  ///< s
    static constexpr int kBins = 50'000;  ///< up to 50 ms

    void add(double seconds)
    {
        const double s = std::max(0.0, seconds);
        const auto bin = static_cast<std::int64_t>(s / kBin);
        ++m_counts[static_cast<size_t>(std::min<std::int64_t>(bin, kBins))];
        ++m_count;
        m_max = std::max(m_max, s);
    }
    [[nodiscard]] std::int64_t count() const { return m_count; }
    [[nodiscard]] double max() const { return m_max; }
    /// The p-quantile (0..1), to the bin's upper edge (the exact maximum for p = 1); 0 when empty.
    [[nodiscard]] double quantile(double p) const
    {
        if (m_count == 0) {
            return 0.0;
        }
        if (p >= 1.0) {
            return m_max;
        }
        const auto rank = static_cast<std::int64_t>(p * static_cast<double>(m_count));
        std::int64_t seen = 0;
        for (int b = 0; b <= kBins; ++b) {
            seen += m_counts[static_cast<size_t>(b)];
            if (seen > rank) {
                return std::min(m_max, (b + 1) * kBin);
            }
        }
        return m_max;
    }

    /// The fraction (0..1) of the durations longer than `seconds`, to the
    /// bin: those in bins wholly above it (the overflow bin counts as above
    /// below 50 ms); 0 when empty or at or above the maximum.
    [[nodiscard]] double fractionAbove(double seconds) const
    {
        if (m_count == 0 || seconds >= m_max) {
            return 0.0;
        }
        const auto first = static_cast<std::int64_t>(std::max(0.0, seconds) / kBin) + 1;
        std::int64_t above = 0;
        for (std::int64_t b = std::min<std::int64_t>(first, kBins); b <= kBins; ++b) {
            above += m_counts[static_cast<size_t>(b)];
        }
        return static_cast<double>(above) / static_cast<double>(m_count);
    }

private:
    std::vector<std::int64_t> m_counts = std::vector<std::int64_t>(kBins + 1, 0);  ///< sized once
    std::int64_t m_count = 0;
    double m_max = 0.0;
};

}  // namespace colonosim::devices
