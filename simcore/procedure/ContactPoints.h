#pragma once
/// \file
/// Where the scope meets the wall: its nodes and, with contact.elementPoints
/// = k > 0, k points inside each element, at t = j / (k + 1) of the way from
/// the element's base-side node to its tip-side one. Points are numbered from
/// the base, each node followed by its element's inner points, so point p
/// lies on element p / (k + 1) at t = (p mod (k + 1)) / (k + 1), and a node
/// entering the rod at its base shifts every point by k + 1.
///
/// The chain's elements are rigid between its joints, so a point on an
/// element moves as a node at that place would: joint i turns it about x_i
/// for every joint i up to the element's base-side node (joints(p)), and a
/// load f at the point acts on the rod as (1 - t) f on the element's
/// base-side node and t f on its tip-side one (the same resultant and the
/// same moment about any point).

#include <Eigen/Core>

#include <vector>

namespace colonosim::procedure {

struct ContactPoints {
    int stride = 1;  ///< points per element: the base-side node and the element's inner points

    [[nodiscard]] int count(int nodes) const { return nodes > 0 ? (nodes - 1) * stride + 1 : 0; }
    /// The element's base-side node.
    [[nodiscard]] int node(int point) const { return point / stride; }
    /// How far along the element from that node, in [0, 1).
    [[nodiscard]] double share(int point) const
    {
        return static_cast<double>(point % stride) / static_cast<double>(stride);
    }
    /// How many joints (from the base) move the point: those before its node,
    /// and the node's own once the point lies past it.
    [[nodiscard]] int joints(int point) const { return node(point) + (point % stride != 0 ? 1 : 0); }
    /// The point on the rod whose node positions are `x`.
    [[nodiscard]] Eigen::Vector3d at(const std::vector<Eigen::Vector3d>& x, int point) const
    {
        const auto a = static_cast<size_t>(node(point));
        if (point % stride == 0) {
            return x[a];
        }
        const double t = share(point);
        return (1.0 - t) * x[a] + t * x[a + 1];
    }
    /// Every point of the nodes' columns `nodes` (3 x n) into `points`.
    void interpolate(const Eigen::Matrix3Xd& nodes, Eigen::Matrix3Xd& points) const
    {
        const int n = static_cast<int>(nodes.cols());
        points.resize(3, count(n));
        for (int p = 0; p < points.cols(); ++p) {
            const int a = node(p);
            if (p % stride == 0) {
                points.col(p) = nodes.col(a);
            } else {
                const double t = share(p);
                points.col(p) = (1.0 - t) * nodes.col(a) + t * nodes.col(a + 1);
            }
        }
    }
};

}  // namespace colonosim::procedure
