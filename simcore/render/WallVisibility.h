#pragma once
/// \file
/// Whether one wall point is in view, by the coverage criteria of
/// CoverageTracker but for a single point and without the ID buffer: inside
/// the fisheye's image circle (fieldOfView), within the working distance,
/// and facing the lens within maxIncidence. Folds between the lens and the
/// point do not hide it here (no occlusion test); the procedure loop uses it
/// at every step for the "lesion in view" signal, where a GPU pass per step
/// would not fit.

#include "simcore/render/FisheyeLens.h"
#include "simcore/render/RenderParameters.h"

#include <Eigen/Core>

namespace colonosim::render {

/// `inward` is the wall's unit normal at `point`, into the lumen.
[[nodiscard]] bool wallPointInView(const CameraPose& camera, const Eigen::Vector3d& point,
                                   const Eigen::Vector3d& inward, const RenderParameters& parameters);

}  // namespace colonosim::render
