#pragma once
/// \file
/// `--require EXPR`: what a training task asks of a case, as a small
/// expression (grammar in docs/case-format.md):
///
///     expression := term { "and" term }
///     term       := [ "not" ] ( comparison | predicate )
///     comparison := metric ( "<=" | ">=" | "<" | ">" | "=" ) number [ "mm" | "cm" ]
///     predicate  := name [ "(" argument { "," argument } ")" ]
///     argument   := size | region
///     size       := number "-" number "mm" | ( "<=" | ">=" | "<" | ">" ) number "mm" | number "mm"
///     region     := "right" | "left" | "proximal" | "distal" | segment name
///
/// e.g. `flat_lesion(6-9mm, right) and boston<=5 and redundant_sigmoid`.
/// Each term knows the generation stage after which it can be decided, so the
/// generator rejects an attempt as early as possible.

#include "case_generator/Case.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace colonosim::cases {

struct Statistics;

class ExpressionError : public std::invalid_argument {
public:
    explicit ExpressionError(const std::string& message) : std::invalid_argument(message) {}
};

/// Generation stages, in order.
enum class Stage : std::uint8_t { Patient, History, Anatomy, Pathology, Environment, Difficulty };

enum class Comparison : std::uint8_t { Less, LessEqual, Equal, GreaterEqual, Greater };

struct RequireTerm {
    enum class Kind : std::uint8_t { Flag, LesionPredicate, Metric };
    Kind kind = Kind::Flag;
    bool negated = false;
    std::string name;
    // Metric comparisons.
    Comparison op = Comparison::Equal;
    double value = 0;  ///< metric units (see docs): counts, years, kg/m^2, cm
    // Lesion predicates: sizes in whole mm (inclusive) and segments allowed.
    int minSizeMm = 0;
    int maxSizeMm = 1000;
    std::vector<Segment> segments;  ///< empty: anywhere
    Stage stage = Stage::Patient;
    std::string text;  ///< canonical text
};

class RequireExpression {
public:
    using Terms = std::vector<RequireTerm>;

    RequireExpression() = default;
    /// Throws ExpressionError naming the column and what was expected.
    static RequireExpression parse(const std::string& text);

    [[nodiscard]] bool empty() const { return m_terms.empty(); }
    [[nodiscard]] const std::vector<RequireTerm>& terms() const { return m_terms; }
    /// Whether every term decidable at `stage` holds for the partial case.
    [[nodiscard]] bool holdsAt(Stage stage, const Case& c, const Statistics& stats) const;
    /// Canonical text, terms joined by " and ".
    [[nodiscard]] std::string text() const;

private:
    Terms m_terms;
};

/// The value of a metric for a case; nullopt for an unknown name.
[[nodiscard]] std::optional<double> metricValue(const std::string& name, const Case& c,
                                                const Statistics& stats);
[[nodiscard]] bool termHolds(const RequireTerm& term, const Case& c, const Statistics& stats);

}  // namespace colonosim::cases
