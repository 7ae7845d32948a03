#pragma once
/// \file
/// The metrics of a session, declared as data: name, unit, which direction is
/// better, and the source that reports them (reference/clinical-assessment.md).
/// Values are SI (s, m, N, N m); shares are fractions 0-1; discomfort is 0-10.

#include <span>
#include <string_view>

namespace colonosim::scoring {

enum class Better { Higher, Lower, Neither };

struct MetricDefinition {
    std::string_view name;   ///< identifier: records, CSV, xAPI, benchmark sets
    std::string_view label;  ///< as a person reads it: the trainer's tables, charts and the PDF
    std::string_view unit;
    Better better;
    std::string_view help;
    std::string_view source;
};

[[nodiscard]] std::span<const MetricDefinition> metricDefinitions();
/// nullptr when `name` is not a declared metric.
[[nodiscard]] const MetricDefinition* findMetric(std::string_view name);

}  // namespace colonosim::scoring
