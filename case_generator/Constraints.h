#pragma once
/// \file
/// What a curriculum task asks of a case (issue 4 §3): sex, an age range, a
/// BMI range, a difficulty range and a require expression. The generator
/// conditions on them: sex and age are drawn from their conditional laws, BMI
/// is redrawn until it falls in range (it depends on sex only), and every
/// other term rejects the attempt at the first stage that decides it, so the
/// accepted cases follow the population law conditioned on the constraints.

#include "case_generator/Case.h"
#include "case_generator/RequireExpression.h"

#include <optional>
#include <string>

namespace colonosim::cases {

struct Statistics;

struct Constraints {
    std::optional<Sex> sex;
    std::optional<int> ageMin, ageMax;     ///< years, inclusive
    std::optional<double> bmiMin, bmiMax;  ///< kg/m^2, inclusive
    std::optional<int> difficultyMin, difficultyMax;
    RequireExpression require;

    [[nodiscard]] bool empty() const;
    /// Canonical text, stored in the case's provenance: "sex=F; bmi_max=22; require=...".
    [[nodiscard]] std::string text() const;
    /// Why no case can satisfy these constraints, judged from the bounds of
    /// the population and of each term; nullopt when none is found (the
    /// generator's attempt budget catches what this does not).
    [[nodiscard]] std::optional<std::string> impossibility(const Statistics& stats) const;
};

}  // namespace colonosim::cases
