#pragma once
/// \file
/// What to improve, in plain words, when a metric misses its benchmark: one
/// sentence per declared metric (scoring/MetricDefinitions.h), saying what
/// to do differently at the scope, not what the number is.

#include <QString>

#include <string_view>

namespace colonosim::app {

/// The advice for `metric`; a general sentence for a metric without its own.
[[nodiscard]] QString adviceFor(std::string_view metric);

}  // namespace colonosim::app
