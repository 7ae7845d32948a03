#include "simcore/physics/TangentPreconditioner.h"

#include <algorithm>
#include <utility>

namespace colonosim::physics {

bool TangentPreconditioner::build(const TissueBody& body)
{
    if (!m_analysed || body.integratedNodes() != m_nodes) {
        m_nodes = body.integratedNodes();
        colour(body);
        m_analysed = false;
    }
    probe(body);
    const auto n = static_cast<Eigen::Index>(m_nodes.size());
    m_matrix.resize(3 * n, 3 * n);
    m_matrix.setFromTriplets(m_entries.begin(), m_entries.end());
    if (!m_analysed) {
        m_factor.analyzePattern(m_matrix);
        m_analysed = true;
    }
    m_factor.factorize(m_matrix);
    if (m_factor.info() != Eigen::Success) {
        return false;
    }
    // A positive definite matrix has a positive diagonal in LDL^T.
    return m_factor.vectorD().size() == 3 * n && (m_factor.vectorD().array() > 0.0).all();
}

void TangentPreconditioner::colour(const TissueBody& body)
{
    const int numNodes = body.numNodes();
    const auto n = static_cast<int>(m_nodes.size());
    std::vector<int> local(static_cast<size_t>(numNodes), -1);
    for (int a = 0; a < n; ++a) {
        local[static_cast<size_t>(m_nodes[static_cast<size_t>(a)])] = a;
    }

    // The coupling graph over the integrated nodes.
    std::vector<std::pair<int, int>> pairs;
    for (const auto& term : body.forceTerms()) {
        term->addCouplings(pairs);
    }
    std::vector<std::vector<int>>& adjacent = m_adjacent;
    adjacent.assign(static_cast<size_t>(n), {});
    for (const auto& [i, j] : pairs) {
        if (i < 0 || j < 0 || i >= numNodes || j >= numNodes || i == j) {
            continue;
        }
        const int a = local[static_cast<size_t>(i)];
        const int b = local[static_cast<size_t>(j)];
        if (a >= 0 && b >= 0) {
            adjacent[static_cast<size_t>(a)].push_back(b);
            adjacent[static_cast<size_t>(b)].push_back(a);
        }
    }
    for (std::vector<int>& list : adjacent) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }

    // Greedy distance-2 colouring: a node takes the lowest colour that no
    // node within two couplings of it has.
    std::vector<int>& colour = m_colour;
    colour.assign(static_cast<size_t>(n), -1);
    std::vector<int> seenBy;  // seenBy[c] == a: colour c is taken near node a
    m_colours = 0;
    for (int a = 0; a < n; ++a) {
        const auto mark = [&](int b) {
            const int c = colour[static_cast<size_t>(b)];
            if (c >= 0) {
                seenBy[static_cast<size_t>(c)] = a;
            }
        };
        for (const int b : adjacent[static_cast<size_t>(a)]) {
            mark(b);
            for (const int d : adjacent[static_cast<size_t>(b)]) {
                mark(d);
            }
        }
        int c = 0;
        while (c < m_colours && seenBy[static_cast<size_t>(c)] == a) {
            ++c;
        }
        if (c == m_colours) {
            ++m_colours;
            seenBy.push_back(-1);
        }
        colour[static_cast<size_t>(a)] = c;
    }
    m_byColour.assign(static_cast<size_t>(m_colours), {});
    for (int a = 0; a < n; ++a) {
        m_byColour[static_cast<size_t>(colour[static_cast<size_t>(a)])].push_back(a);
    }
}

void TangentPreconditioner::probe(const TissueBody& body)
{
    const auto n = static_cast<int>(m_nodes.size());
    const std::vector<int>& colour = m_colour;
    const std::vector<std::vector<int>>& adjacent = m_adjacent;

    // One product per colour and axis: row block j of K e gives K_ji for the
    // one node i of that colour coupled to j (or j itself).
    std::vector<Eigen::Triplet<double>>& entries = m_entries;
    entries.clear();
    Eigen::Matrix3Xd dx = Eigen::Matrix3Xd::Zero(3, body.numNodes());
    Eigen::Matrix3Xd df;
    for (int c = 0; c < m_colours; ++c) {
        const std::vector<int>& members = m_byColour[static_cast<size_t>(c)];
        for (int axis = 0; axis < 3; ++axis) {
            for (const int a : members) {
                dx(axis, m_nodes[static_cast<size_t>(a)]) = 1.0;
            }
            body.declaredStiffnessProduct(body.positions(), dx, df);
            for (const int a : members) {
                dx(axis, m_nodes[static_cast<size_t>(a)]) = 0.0;
            }
            for (int row = 0; row < n; ++row) {
                int column = colour[static_cast<size_t>(row)] == c ? row : -1;
                if (column < 0) {
                    for (const int b : adjacent[static_cast<size_t>(row)]) {
                        if (colour[static_cast<size_t>(b)] == c) {
                            column = b;
                            break;
                        }
                    }
                }
                if (column < 0) {
                    continue;
                }
                const Eigen::Vector3d block = df.col(m_nodes[static_cast<size_t>(row)]);
                for (int r = 0; r < 3; ++r) {
                    // -K+, symmetrised: half here and half transposed.
                    const double value = -0.5 * block[r];
                    entries.emplace_back(3 * row + r, 3 * column + axis, value);
                    entries.emplace_back(3 * column + axis, 3 * row + r, value);
                }
            }
        }
    }
}

void TangentPreconditioner::apply(const Eigen::Matrix3Xd& r, Eigen::Matrix3Xd& z) const
{
    const auto n = static_cast<Eigen::Index>(m_nodes.size());
    m_rhs.resize(3 * n);
    for (Eigen::Index a = 0; a < n; ++a) {
        m_rhs.segment<3>(3 * a) = r.col(m_nodes[static_cast<size_t>(a)]);
    }
    m_solution = m_factor.solve(m_rhs);
    z.setZero(3, r.cols());
    for (Eigen::Index a = 0; a < n; ++a) {
        z.col(m_nodes[static_cast<size_t>(a)]) = m_solution.segment<3>(3 * a);
    }
}

}  // namespace colonosim::physics
