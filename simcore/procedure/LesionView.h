#pragma once
/// \file
/// Which of the case's lesions the camera shows, step by step: the signal
/// behind "lesion detected" (a lesion marked while in view) and the time to
/// detection.
///
/// Each lesion sits at its place on the wall (arc length along the
/// centreline and clock angle, as the case gives it), carried by the wall
/// node nearest that place at rest, so it moves with the deforming wall. Its
/// normal is the node's (the mean of its triangles' normals, turned into the
/// lumen). In view means render::wallPointInView: inside the fisheye's
/// image circle, within the working distance and facing the lens; folds in
/// between do not hide it (see WallVisibility.h).

#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/procedure/WallSite.h"
#include "simcore/render/RenderParameters.h"
#include "simcore/scope/Colonoscope.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace colonosim::procedure {

/// A lesion's place on the wall.
using LesionSite = WallSite;

class LesionView {
public:
    /// At most kMaxLesions sites, each within the colon's length; throws
    /// params::ParameterError naming the lesion, the value and the range.
    LesionView(const geometry::ColonAnatomy& anatomy, const std::vector<LesionSite>& sites,
               const render::RenderParameters& viewing);

    static constexpr int kMaxLesions = 32;

    /// Bit k set when lesion k is in view from `tip` on the wall `positions`.
    [[nodiscard]] std::uint32_t inView(const Eigen::Matrix3Xd& positions, const scope::TipPose& tip) const;

    [[nodiscard]] int count() const { return static_cast<int>(m_node.size()); }
    /// The wall node carrying lesion k.
    [[nodiscard]] int node(int k) const { return m_node[static_cast<size_t>(k)]; }
    /// The wall triangles around lesion k's node (indices into the
    /// anatomy's physicsMesh): what the renderer's coverage looks for.
    [[nodiscard]] const std::vector<int>& triangles(int k) const
    {
        return m_triangles[static_cast<size_t>(k)];
    }

private:
    const geometry::ColonAnatomy& m_anatomy;
    render::RenderParameters m_viewing;
    std::vector<int> m_node;
    std::vector<std::vector<int>> m_triangles;  ///< triangles around each lesion's node
};

}  // namespace colonosim::procedure
