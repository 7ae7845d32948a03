#pragma once
/// \file
/// The generator: a seed drives the whole chain, patient -> indication ->
/// history -> anatomy -> pathology -> tuning -> environment -> difficulty.
///
/// Constraints are met by rejection sampling (Constraints.h): attempt k uses
/// its own stream Random(seed, k), and is abandoned at the first stage whose
/// terms fail; the first accepted attempt is the case, and its number is
/// stored with the seed, so `seed + constraints` reproduce it exactly. A
/// constraint set that the bounds show impossible is refused before any
/// attempt; one that no attempt meets within the budget is reported as
/// impossible or too rare.

#include "case_generator/Case.h"
#include "case_generator/Constraints.h"
#include "case_generator/Statistics.h"

#include <cstdint>
#include <stdexcept>

namespace colonosim::cases {

/// Bumped whenever the same seed would give a different case.
inline constexpr const char* kGeneratorVersion = "1.0";
inline constexpr int kFormatVersion = 1;
inline constexpr std::uint64_t kAttemptBudget = 200000;

/// The constraints cannot be met; the message says which and why.
class ImpossibleConstraints : public std::invalid_argument {
public:
    explicit ImpossibleConstraints(const std::string& message) : std::invalid_argument(message) {}
};

class CaseGenerator {
public:
    explicit CaseGenerator(const Statistics& stats = Statistics::builtIn()) : m_stats(stats) {}

    /// Throws ImpossibleConstraints.
    [[nodiscard]] Case generate(std::uint64_t seed, const Constraints& constraints = {}) const;
    /// One attempt; false when it is rejected (`c` is then partly filled).
    /// Throws ImpossibleConstraints when the BMI range is out of reach.
    [[nodiscard]] bool attempt(std::uint64_t seed, std::uint64_t attemptNumber,
                               const Constraints& constraints, Case& c) const;
    [[nodiscard]] const Statistics& statistics() const { return m_stats; }

private:
    const Statistics& m_stats;
};

}  // namespace colonosim::cases
