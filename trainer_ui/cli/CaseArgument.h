#pragma once
/// \file
/// The `--case FILE` argument shared by the subcommands that simulate a case.

#include "case_generator/Case.h"
#include "case_generator/SceneSpec.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <string>

namespace colonosim::cli {

/// Reads and validates the case file; throws UsageError listing every
/// `file:line: message` when it is not a valid case.
[[nodiscard]] cases::Case readCaseArgument(const std::string& path);

/// The procedure settings a case's scene sets: the wall, the environment and
/// the lesions' places (for the "lesion in view" signal). Diverticula and
/// adhesions are not yet part of the loop's physics.
[[nodiscard]] procedure::ProcedureSettings procedureSettingsFor(const cases::SceneSpec& scene);

}  // namespace colonosim::cli
