#pragma once
/// \file
/// What a case puts on the colon wall for the renderer: its lesions (shape
/// from the Paris class, colour from the histology: hyperplastic and
/// serrated histologies as serrated, adenocarcinoma as cancer, lipoma as
/// lipoma, the adenomas as adenoma), diverticula, the residual stool of
/// each segment and the residual fluid of each bowel region (a pool free to
/// flow within the region's segments), from its preparation, and gravity's
/// direction from the patient's position.

#include "case_generator/SceneSpec.h"
#include "simcore/render/WallSurface.h"

namespace colonosim::cli {

[[nodiscard]] render::WallFindings findingsOf(const cases::SceneSpec& scene);

}  // namespace colonosim::cli
