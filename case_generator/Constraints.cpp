#include "case_generator/Constraints.h"

#include "case_generator/CaseNames.h"
#include "case_generator/Quantity.h"
#include "case_generator/Statistics.h"
#include "simcore/geometry/AnatomyParameters.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace colonosim::cases {

namespace {

/// A closed interval of values a metric may take; integer metrics move strict
/// bounds by one, continuous ones by a tiny step.
struct Interval {
    double lo;
    double hi;
    bool integer;

    void apply(Comparison op, double value, bool negated)
    {
        if (negated) {
            switch (op) {
            case Comparison::Less: op = Comparison::GreaterEqual; break;
            case Comparison::LessEqual: op = Comparison::Greater; break;
            case Comparison::GreaterEqual: op = Comparison::Less; break;
            case Comparison::Greater: op = Comparison::LessEqual; break;
            case Comparison::Equal: return;  // "not =" removes one point only
            }
        }
        const double step = integer ? 1.0 : 1e-9;
        switch (op) {
        case Comparison::Less: hi = std::min(hi, integer ? std::ceil(value) - step : value - step); break;
        case Comparison::LessEqual: hi = std::min(hi, integer ? std::floor(value) : value); break;
        case Comparison::Equal:
            lo = std::max(lo, value);
            hi = std::min(hi, value);
            if (integer && value != std::floor(value)) {
                hi = lo - 1.0;
            }
            break;
        case Comparison::GreaterEqual: lo = std::max(lo, integer ? std::ceil(value) : value); break;
        case Comparison::Greater: lo = std::max(lo, integer ? std::floor(value) + step : value + step); break;
        }
    }
    [[nodiscard]] bool empty() const { return lo > hi; }
};

std::string formatBound(double x)
{
    return formatFixed(x, x == std::floor(x) ? 0 : 1);
}

std::map<std::string, Interval> metricSupport(const Statistics& stats)
{
    using geometry::AnatomyParameters;
    double minTotal = 0.0;
    double maxTotal = 0.0;
    for (const auto& field : AnatomyParameters::fields().first(geometry::kNumSegments)) {
        minTotal += field.spec->minValue;
        maxTotal += field.spec->maxValue;
    }
    return {
        {"age", {static_cast<double>(stats.minAge()), static_cast<double>(stats.maxAge()), true}},
        {"bmi", {stats.bmi.lo, stats.bmi.hi, false}},
        {"colon_length", {minTotal * 100.0, maxTotal * 100.0, false}},
        {"sigmoid_length",
         {AnatomyParameters::sigmoidLengthSpec.minValue * 100,
          AnatomyParameters::sigmoidLengthSpec.maxValue * 100, false}},
        {"transverse_length",
         {AnatomyParameters::transverseLengthSpec.minValue * 100,
          AnatomyParameters::transverseLengthSpec.maxValue * 100, false}},
        {"lesions", {0, 1000, true}},
        {"adenomas", {0, 1000, true}},
        {"diverticula", {0, 40, true}},
        {"hemorrhoid_grade", {0, 4, true}},
        {"boston", {0, 9, true}},
        {"boston_right", {0, 3, true}},
        {"boston_transverse", {0, 3, true}},
        {"boston_left", {0, 3, true}},
        {"difficulty", {1, 5, true}},
    };
}

/// The sizes (mm) a lesion predicate can match at all.
std::pair<int, int> possibleSizes(const std::string& name, const Statistics& stats)
{
    int largest = 0;
    for (const IntRange& r : stats.largeSizeRanges) {
        largest = std::max(largest, r.hi);
    }
    if (name == "cancer") {
        return {stats.cancerSize.lo, stats.cancerSize.hi};
    }
    if (name == "lipoma") {
        return {stats.lipomaSizeRange.lo, stats.lipomaSizeRange.hi};
    }
    if (name == "lst") {
        return {10, largest};
    }
    if (name == "advanced_adenoma" || name == "adenoma" || name == "serrated_lesion" ||
        name == "sessile_serrated_lesion" || name == "hyperplastic_polyp" || name == "flat_lesion" ||
        name == "depressed_lesion") {
        return {stats.smallSizes[0].front(), largest};
    }
    return {stats.smallSizes[0].front(), std::max({largest, stats.cancerSize.hi, stats.lipomaSizeRange.hi})};
}

}  // namespace

bool Constraints::empty() const
{
    return !sex && !ageMin && !ageMax && !bmiMin && !bmiMax && !difficultyMin && !difficultyMax &&
           require.empty();
}

std::string Constraints::text() const
{
    std::string out;
    const auto add = [&out](const std::string& item) { out += (out.empty() ? "" : "; ") + item; };
    if (sex) {
        add("sex=" + std::string(nameOf(*sex)));
    }
    if (ageMin) {
        add("age_min=" + std::to_string(*ageMin));
    }
    if (ageMax) {
        add("age_max=" + std::to_string(*ageMax));
    }
    if (bmiMin) {
        add("bmi_min=" + formatBound(*bmiMin));
    }
    if (bmiMax) {
        add("bmi_max=" + formatBound(*bmiMax));
    }
    if (difficultyMin || difficultyMax) {
        add("difficulty=" + std::to_string(difficultyMin.value_or(1)) + "-" +
            std::to_string(difficultyMax.value_or(5)));
    }
    if (!require.empty()) {
        add("require=" + require.text());
    }
    return out;
}

std::optional<std::string> Constraints::impossibility(const Statistics& stats) const
{
    std::map<std::string, Interval> support = metricSupport(stats);
    const std::map<std::string, Interval> population = support;
    if (ageMin) {
        support.at("age").apply(Comparison::GreaterEqual, *ageMin, false);
    }
    if (ageMax) {
        support.at("age").apply(Comparison::LessEqual, *ageMax, false);
    }
    if (bmiMin) {
        support.at("bmi").apply(Comparison::GreaterEqual, *bmiMin, false);
    }
    if (bmiMax) {
        support.at("bmi").apply(Comparison::LessEqual, *bmiMax, false);
    }
    if (difficultyMin) {
        support.at("difficulty").apply(Comparison::GreaterEqual, *difficultyMin, false);
    }
    if (difficultyMax) {
        support.at("difficulty").apply(Comparison::LessEqual, *difficultyMax, false);
    }
    for (const RequireTerm& term : require.terms()) {
        if (term.kind == RequireTerm::Kind::Metric) {
            support.at(term.name).apply(term.op, term.value, term.negated);
        } else if (term.kind == RequireTerm::Kind::LesionPredicate && !term.negated) {
            support.at("lesions").apply(Comparison::GreaterEqual, 1, false);
            const auto [lo, hi] = possibleSizes(term.name, stats);
            if (term.minSizeMm > hi || term.maxSizeMm < lo) {
                return term.text + ": the generator makes no such lesion outside " + std::to_string(lo) +
                       "-" + std::to_string(hi) + " mm";
            }
            if (term.name == "adenoma" || term.name == "advanced_adenoma") {
                support.at("adenomas").apply(Comparison::GreaterEqual, 1, false);
            }
        } else if (term.kind == RequireTerm::Kind::Flag && !term.negated) {
            if (term.name == "hysterectomy" && sex == Sex::Male) {
                return "hysterectomy asks for a woman, but sex=M";
            }
            if (term.name == "diverticulosis" || term.name == "severe_diverticulosis") {
                support.at("diverticula")
                    .apply(Comparison::GreaterEqual, term.name == "diverticulosis" ? 1 : 11, false);
            }
            if (term.name == "hemorrhoids") {
                support.at("hemorrhoid_grade").apply(Comparison::GreaterEqual, 1, false);
            }
        }
        for (const RequireTerm& other : require.terms()) {
            if (!term.negated && other.negated && other.text == "not " + term.text) {
                return term.text + " and " + other.text + " contradict each other";
            }
        }
    }
    for (const auto& [name, interval] : support) {
        if (interval.empty()) {
            const Interval& all = population.at(name);
            return "no value of " + name + " meets every bound given (" + name + " lies in " +
                   formatBound(all.lo) + "-" + formatBound(all.hi) + " in the generated population)";
        }
    }
    return std::nullopt;
}

}  // namespace colonosim::cases
