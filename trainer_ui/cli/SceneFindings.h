#pragma once
/// \file
/// What a case puts on the colon wall for the renderer: its lesions (shape
/// from the Paris class, colour from the histology), diverticula and the
/// residual stool of each segment (from its bowel region's preparation).

#include "case_generator/SceneSpec.h"
#include "simcore/render/WallSurface.h"

namespace colonosim::cli {

[[nodiscard]] render::WallFindings findingsOf(const cases::SceneSpec& scene);

}  // namespace colonosim::cli
