#pragma once
/// \file
/// The entries of a force term that act on awake nodes (ActiveRegion.h).
///
/// The integrators move only awake, free nodes and never read the force on
/// a sleeping one, so a term with one entry per node (gravity, drag) or per
/// tether or anchor sums its force over these entries only: a quiet colon
/// then costs in proportion to its awake part, not to its whole mesh. The
/// list is rebuilt when the active set changes (rarely) and appended to as
/// entries are added; an empty flag vector means every node is awake.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace colonosim::physics {

class AwakeEntries {
public:
    /// Entry `entry` acts on `node`: keeps it when that node is awake.
    void append(int entry, int node)
    {
        if (isAwake(node)) {
            m_entries.push_back(entry);
        }
    }

    /// Rebuilds from the node of each entry and the new flags.
    void rebuild(const std::vector<int>& nodeOfEntry, const std::vector<std::uint8_t>& awake)
    {
        m_awake = awake;
        m_entries.clear();
        for (std::size_t e = 0; e < nodeOfEntry.size(); ++e) {
            append(static_cast<int>(e), nodeOfEntry[e]);
        }
    }

    /// Rebuilds for a term whose entry i is node i, of `numNodes` nodes.
    void rebuildPerNode(int numNodes, const std::vector<std::uint8_t>& awake)
    {
        m_awake = awake;
        rebuildPerNode(numNodes);
    }

    /// The same after the number of nodes changed, with the last flags.
    void rebuildPerNode(int numNodes)
    {
        m_entries.clear();
        for (int i = 0; i < numNodes; ++i) {
            append(i, i);
        }
    }

    [[nodiscard]] const std::vector<int>& entries() const { return m_entries; }

private:
    [[nodiscard]] bool isAwake(int node) const
    {
        const auto i = static_cast<std::size_t>(node);
        return m_awake.empty() || i >= m_awake.size() || m_awake[i] != 0;
    }

    std::vector<std::uint8_t> m_awake;
    std::vector<int> m_entries;
};

}  // namespace colonosim::physics
