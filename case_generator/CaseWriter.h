#pragma once
/// \file
/// Writes a case as XML (format: docs/case-format.md, schema:
/// case_generator/schema/case.xsd). Numbers are fixed-point with the decimals
/// their Quantity declares, so the same case always gives the same bytes.

#include "case_generator/Case.h"

#include <string>

namespace colonosim::cases {

[[nodiscard]] std::string writeCase(const Case& c);
/// Throws std::runtime_error naming the file when it cannot be written.
void writeCaseFile(const Case& c, const std::string& path);

}  // namespace colonosim::cases
