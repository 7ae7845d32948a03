#include "simcore/physics/NodeGather.h"

#include <algorithm>

namespace colonosim::physics {

void NodeGather::build(std::span<const int> nodes, std::span<const double> signs)
{
    const size_t arity = signs.size();
    m_items = arity > 0 ? nodes.size() / arity : 0;
    int count = 0;
    for (const int n : nodes) {
        count = std::max(count, n + 1);
    }
    // Count each node's entries, then place them item by item: within a
    // node the entries follow the items' order.
    std::vector<int>& entries = m_count;
    entries.assign(static_cast<size_t>(count), 0);
    for (const int n : nodes) {
        ++entries[static_cast<size_t>(n)];
    }
    m_nodes.clear();
    m_first.clear();
    std::vector<int>& slot = m_slot;
    slot.assign(static_cast<size_t>(count), 0);
    int total = 0;
    for (int n = 0; n < count; ++n) {
        if (entries[static_cast<size_t>(n)] > 0) {
            m_nodes.push_back(n);
            m_first.push_back(total);
            slot[static_cast<size_t>(n)] = total;
            total += entries[static_cast<size_t>(n)];
        }
    }
    m_first.push_back(total);
    m_item.resize(static_cast<size_t>(total));
    m_sign.resize(static_cast<size_t>(total));
    for (size_t e = 0; e < nodes.size(); ++e) {
        const int a = slot[static_cast<size_t>(nodes[e])]++;
        m_item[static_cast<size_t>(a)] = static_cast<int>(e / arity);
        m_sign[static_cast<size_t>(a)] = signs[e % arity];
    }
}

namespace {

/// NodeGather::sumInto(), with the gate looked at only when `Gated`.
template <bool Gated>
void sumNodes(const std::vector<int>& nodes, const std::vector<int>& first, const int* item,
              const double* sign, double* f, const double* fx, const double* fy, const double* fz,
              const double* gate, double below)
{
    // sign * force is exact (a negation or none), and a + (-b) is a - b in
    // IEEE arithmetic: each addition is the one the items' order makes.
    for (size_t k = 0; k < nodes.size(); ++k) {
        double* fn = f + 3 * static_cast<size_t>(nodes[k]);
        double sx = fn[0];
        double sy = fn[1];
        double sz = fn[2];
        const int last = first[k + 1];
        for (int a = first[k]; a < last; ++a) {
            const auto s = static_cast<size_t>(item[a]);
            if (Gated && gate[s] < below) {
                continue;
            }
            sx += sign[a] * fx[s];
            sy += sign[a] * fy[s];
            sz += sign[a] * fz[s];
        }
        fn[0] = sx;
        fn[1] = sy;
        fn[2] = sz;
    }
}

}  // namespace

void NodeGather::sumInto(double* f, const double* fx, const double* fy, const double* fz, const double* gate,
                         double below) const
{
    if (gate != nullptr) {
        sumNodes<true>(m_nodes, m_first, m_item.data(), m_sign.data(), f, fx, fy, fz, gate, below);
    } else {
        sumNodes<false>(m_nodes, m_first, m_item.data(), m_sign.data(), f, fx, fy, fz, gate, below);
    }
}

}  // namespace colonosim::physics
