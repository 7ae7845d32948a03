#pragma once
/// \file
/// The `--case FILE` argument shared by the subcommands that simulate a case.

#include "case_generator/Case.h"

#include <string>

namespace colonosim::cli {

/// Reads and validates the case file; throws UsageError listing every
/// `file:line: message` when it is not a valid case.
[[nodiscard]] cases::Case readCaseArgument(const std::string& path);

}  // namespace colonosim::cli
