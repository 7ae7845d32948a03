#pragma once
/// \file
/// Maps a high-resolution visual mesh onto a deformed low-resolution physics
/// mesh (de Visser et al., IJIG 2010, section 2.3, and de Visser et al. 2008).
///
/// Smooth normal field on the physics mesh: vertex normals n_k are the
/// area-weighted sums of the adjacent face normals, normalised; inside a
/// triangle n(b) = (sum_k b_k n_k) / |sum_k b_k n_k|. Each visual vertex v is
/// bound to one physics triangle (x_0, x_1, x_2) by barycentric coordinates
/// b and an offset d along the interpolated normal:
///
///     v = sum_k b_k x_k + d n(b).
///
/// (b, d) is solved at rest by Newton's method (3 unknowns: b_1, b_2, d, with
/// b_0 = 1 - b_1 - b_2) so the rest round trip is exact to rounding. The
/// triangle is the nearest one (TriangleGrid) whose solution has b inside the
/// triangle; because n(b) is continuous across edges the mapped surface has no
/// cracks. apply() evaluates the same formula on the deformed physics mesh.

#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

namespace colonosim::geometry {

class TriangleGrid;

class MeshMapping {
public:
    /// One visual vertex: the three physics nodes, their barycentric weights
    /// and the offset along the interpolated normal (m).
    struct Binding {
        std::array<int, 3> node{};
        Eigen::Vector3d weight = Eigen::Vector3d::Zero();
        double offset = 0.0;
    };

    MeshMapping() = default;

    /// Binds every column of `visualRest` to `physicsRest`. Throws
    /// std::invalid_argument when either is empty.
    MeshMapping(const TriangleMesh& physicsRest, const Eigen::Matrix3Xd& visualRest);

    /// Writes the mapped visual vertices for the physics node positions
    /// `physicsPositions` (one column per physics node). Allocates nothing once
    /// `visualOut` has numVisualVertices() columns and after the first call.
    /// Not thread-safe: it uses internal scratch normals.
    void apply(const Eigen::Matrix3Xd& physicsPositions, Eigen::Matrix3Xd& visualOut) const;

    /// Re-binds only `visualVertices` after a topology edit (e.g. a snare
    /// cut). `physicsRest` is the edited physics mesh at rest; the edit must
    /// keep the indices of the nodes it did not remove (new nodes are
    /// appended), so the other bindings stay valid.
    void remap(std::span<const int> visualVertices, const TriangleMesh& physicsRest);

    [[nodiscard]] int numVisualVertices() const { return static_cast<int>(m_bindings.size()); }
    [[nodiscard]] const std::vector<Binding>& bindings() const { return m_bindings; }
    /// Largest |v - sum b_k x_k - d n(b)| left by the rest solve, m.
    [[nodiscard]] double maxRestResidual() const { return m_maxRestResidual; }

    /// Area-weighted, normalised vertex normals (the smooth normal field).
    static void computeVertexNormals(const Eigen::Matrix3Xd& positions,
                                     const std::vector<std::array<int, 3>>& triangles,
                                     Eigen::Matrix3Xd& normals);

private:
    void bindVertices(std::span<const int> visualVertices, const TriangleMesh& physicsRest);

    std::vector<std::array<int, 3>> m_triangles;
    Eigen::Matrix3Xd m_visualRest;
    std::vector<Binding> m_bindings;
    double m_maxRestResidual = 0.0;
    mutable Eigen::Matrix3Xd m_normals;  ///< scratch for apply()
};

}  // namespace colonosim::geometry
