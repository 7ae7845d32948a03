#pragma once
/// \file
/// Per-item forces (a spring's, a triangle's) summed into their nodes node by
/// node, in the items' order: each node's running sum is held in registers and
/// stored once, and receives the same additions in the same order as adding
/// the items into the nodes one after the other, so the sums are the same bit
/// for bit. Adding item after item into the nodes instead makes consecutive
/// items of one node wait for each other's stores (SpringKernel.h).

#include <span>
#include <vector>

namespace colonosim::physics {

class NodeGather {
public:
    /// From each item's nodes, item after item: `nodes[item * arity + k]` is
    /// item's k-th node, with arity = signs.size(); `signs[k]` is +1 or -1,
    /// the sign with which an item's force reaches its k-th node.
    void build(std::span<const int> nodes, std::span<const double> signs);
    [[nodiscard]] size_t numItems() const { return m_items; }

    /// f (3 x nodes, column-major) += each item's force (fx, fy, fz: N, one
    /// per item) with its sign, node by node in the items' order. An item
    /// whose gate (one per item; none when null) is below `below` adds nothing.
    void sumInto(double* f, const double* fx, const double* fy, const double* fz,
                 const double* gate = nullptr, double below = 0.0) const;

private:
    size_t m_items = 0;
    std::vector<int> m_nodes;    ///< nodes with at least one item, ascending
    std::vector<int> m_first;    ///< per node of m_nodes, its first entry; one past the last at the back
    std::vector<int> m_item;     ///< per entry: the item, in the items' order within a node
    std::vector<double> m_sign;  ///< per entry: the sign of the item's force on the node
    // build()'s per-node counts and next free entries, kept so that a rebuild
    // (the active set changes within the loop) reuses their storage.
    std::vector<int> m_count, m_slot;
};

}  // namespace colonosim::physics
