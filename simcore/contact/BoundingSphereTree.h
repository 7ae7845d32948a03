#pragma once
/// \file
/// A bounding-sphere hierarchy over the wall triangles with an enabled flag
/// per leaf (NASA colonoscopy paper, "Collision Detection": hierarchical
/// bounding spheres, each leaf a triangle, "for enabled leafs, the enabled
/// value was propagated to parent nodes" so that queries search only the
/// active part of the tree).
///
/// Model: built once, top-down, by a median split of the triangle centroids
/// along the longest axis of their bounding box; one triangle per leaf. The
/// topology never changes: each step refit() recomputes the spheres
/// bottom-up from the current vertex positions. A leaf's sphere is centred
/// on the triangle's centroid with radius the largest centroid-vertex
/// distance; a parent's sphere is the smallest sphere enclosing its two
/// children's spheres. A parent is enabled when either child is; refit and
/// queries visit enabled nodes only. A disabled subtree is left as it was:
/// its triangles belong to sleeping nodes that do not move, and it is refit
/// again before any query once enabled.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace colonosim::contact {

class BoundingSphereTree {
public:
    struct Node {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< m
        double radius = 0.0;                               ///< m
        int left = -1;                                     ///< child index; -1 for a leaf
        int right = -1;                                    ///< child index; -1 for a leaf
        int triangle = -1;                                 ///< triangle of a leaf; -1 otherwise
        std::uint8_t enabled = 1;
    };

    BoundingSphereTree() = default;
    /// Builds the hierarchy over `triangles` (vertex indices into the columns
    /// of `positions`) and fits it to `positions`; every leaf enabled.
    BoundingSphereTree(const Eigen::Matrix3Xd& positions, std::vector<std::array<int, 3>> triangles);

    [[nodiscard]] int numNodes() const { return static_cast<int>(m_nodes.size()); }
    [[nodiscard]] int numTriangles() const { return static_cast<int>(m_triangles.size()); }
    [[nodiscard]] const Node& node(int index) const { return m_nodes[static_cast<size_t>(index)]; }
    [[nodiscard]] int leafOf(int triangle) const { return m_leafOfTriangle[static_cast<size_t>(triangle)]; }
    [[nodiscard]] const std::vector<std::array<int, 3>>& triangles() const { return m_triangles; }

    /// Recomputes the spheres of the enabled nodes, bottom-up, from `positions`.
    void refit(const Eigen::Matrix3Xd& positions);

    /// Leaf flags: a triangle is enabled when any of its vertices is awake
    /// (one flag per vertex); then propagated to the parents.
    void setEnabledFromNodes(std::span<const std::uint8_t> awake);
    /// Sets one leaf's flag; call propagateEnabled() after a batch of changes.
    void setTriangleEnabled(int triangle, bool enabled);
    void enableAll();
    /// A parent is enabled when any child is.
    void propagateEnabled();
    [[nodiscard]] int numEnabledTriangles() const;

    /// Appends to `out` every enabled triangle whose leaf sphere comes within
    /// `radius` of the segment [p0, p1] (a capsule; p0 == p1 is a sphere).
    /// Returns the number of tree nodes visited; lists them in `visited` when given.
    int queryCapsule(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius,
                     std::vector<int>& out, std::vector<int>* visited = nullptr) const;
    int querySphere(const Eigen::Vector3d& centre, double radius, std::vector<int>& out) const
    {
        return queryCapsule(centre, centre, radius, out);
    }

private:
    int build(std::vector<int>& order, int begin, int end, const std::vector<Eigen::Vector3d>& centroids);
    void fitLeaf(Node& leaf, const Eigen::Matrix3Xd& positions) const;

    std::vector<std::array<int, 3>> m_triangles;
    std::vector<Node> m_nodes;  ///< parents before children; root at 0
    std::vector<int> m_leafOfTriangle;
};

/// Squared distance from `point` to the segment [p0, p1], m^2.
[[nodiscard]] double squaredDistancePointSegment(const Eigen::Vector3d& point, const Eigen::Vector3d& p0,
                                                 const Eigen::Vector3d& p1);

}  // namespace colonosim::contact
