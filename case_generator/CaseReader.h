#pragma once
/// \file
/// Reads and validates a case file. Every problem is reported as
/// `file:line: message`, the message naming the field, the value and what is
/// allowed; reading goes on after an error so one run reports them all, and
/// a case is returned only when there is none. Checked:
/// - well-formed XML (tinyxml2's error and line);
/// - the root <case> and its format_version (a newer version is refused);
/// - unknown elements and attributes, missing and repeated fields;
/// - every number's unit attribute, present and exactly the declared unit;
/// - numbers: plain decimals, finite, within their declared range (the
///   simulator's AnatomyParameters and TissueParameters ranges where they apply);
/// - names from their fixed lists (sex, segment, Paris class, ...);
/// - places that cannot be: a position beyond its segment's length, a lesion
///   larger than its lumen's circumference, a diverticulum in the rectum, a
///   hysterectomy in a man, a BMI that does not match weight and height.
/// Nothing is defaulted: a missing value is an error.

#include "case_generator/Case.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace colonosim::cases {

struct ReadResult {
    std::optional<Case> value;
    std::vector<std::string> errors;  ///< "file:line: message"
    [[nodiscard]] bool ok() const { return value.has_value(); }
};

/// `fileName` prefixes the messages.
[[nodiscard]] ReadResult readCase(std::string_view text, const std::string& fileName);
[[nodiscard]] ReadResult readCaseFile(const std::string& path);

}  // namespace colonosim::cases
