#pragma once
/// \file
/// The procedure settings a case's scene sets: the wall's tissue, the
/// environment, the lesions' places (for the "lesion in view" signal) and
/// the adhesions (anchor springs on the wall). Diverticula are drawn by the
/// renderer and are not part of the loop's physics.

#include "case_generator/SceneSpec.h"
#include "simcore/procedure/ProcedureLoop.h"

namespace colonosim::cases {

[[nodiscard]] procedure::ProcedureSettings procedureSettings(const SceneSpec& scene);

}  // namespace colonosim::cases
