#pragma once
/// \file
/// The rates self-check (`colonosim case stats`): generates n cases and sets
/// each realised rate next to the rate the data file implies for the same
/// population, with its source.
///
/// Expected values are exact functions of the data file: a rate that depends
/// on age or sex is averaged over the age and sex mix, restricted to the
/// sex and age constraints. Other constraints (BMI, difficulty, require) change
/// the population and are not folded into the expected values.
///
/// Each entry has a z score: (realised - expected) / sqrt(p (1 - p) / n) for
/// a proportion, (mean - expected) / (s / sqrt(n)) for a mean. The tests bound
/// |z| by 4.5 (two-sided p = 7e-6 per entry, 2e-4 over the ~40 entries).

#include "case_generator/CaseGenerator.h"

#include <cstdint>
#include <string>
#include <vector>

namespace colonosim::cases {

struct RateEntry {
    std::string name;
    std::string source;
    double expected = 0;
    double realised = 0;
    std::uint64_t trials = 0;  ///< cases, patients or lesions the rate is over
    bool mean = false;         ///< a mean rather than a proportion
    double sd = 0;             ///< sample SD, for means
    [[nodiscard]] double z() const;
};

/// Generates cases seed, seed + 1, ... seed + n - 1 under the constraints.
/// Throws ImpossibleConstraints.
[[nodiscard]] std::vector<RateEntry> checkRates(const CaseGenerator& generator, std::uint64_t n,
                                                std::uint64_t seed, const Constraints& constraints);

}  // namespace colonosim::cases
