#pragma once
/// \file
/// The procedure settings a case's scene sets: the wall's tissue, the
/// environment, the lesions' places (for the "lesion in view" signal) and
/// the adhesions (anchor springs on the wall). Diverticula are drawn by the
/// renderer and are not part of the loop's physics.

#include "case_generator/Case.h"
#include "case_generator/SceneSpec.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <optional>
#include <string>

namespace colonosim::cases {

[[nodiscard]] procedure::ProcedureSettings procedureSettings(const SceneSpec& scene);

/// Why the cecum of case `c` is out of the simulated scope's reach, as a
/// sentence, or nullopt: its colon is longer than the working length of the
/// scope the procedure settings give, and the simulated colon pleats onto the
/// shaft by a few centimetres only (docs/known-limits.md, "Out of scope, not
/// stalled"). The core curriculum draws no such colon.
[[nodiscard]] std::optional<std::string> cecumOutOfReach(const Case& c);

}  // namespace colonosim::cases
