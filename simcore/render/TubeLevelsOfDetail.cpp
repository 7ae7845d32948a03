#include "simcore/render/TubeLevelsOfDetail.h"

#include <algorithm>
#include <limits>

namespace colonosim::render {

namespace {

constexpr int stepOf(int level)
{
    return 1 << level;
}

constexpr size_t variant(int startLevel, int endLevel)
{
    return static_cast<size_t>(startLevel * (TubeLevelsOfDetail::kMaxLevel + 1) + endLevel);
}

std::vector<int> uniqueVertices(const std::vector<std::array<int, 3>>& triangles, size_t first, size_t last)
{
    std::vector<int> vertices;
    vertices.reserve(3 * (last - first));
    for (size_t t = first; t < last; ++t) {
        vertices.insert(vertices.end(), triangles[t].begin(), triangles[t].end());
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

}  // namespace

std::optional<TubeGrid> findTubeGrid(const std::vector<std::array<int, 3>>& triangles, int numVertices)
{
    if (triangles.size() < 2 || triangles[0][0] != 0 || triangles[0][1] != 1) {
        return std::nullopt;
    }
    TubeGrid grid;
    grid.perRing = triangles[0][2];
    const int p = grid.perRing;
    if (p < 3 || numVertices < 2 * p) {
        return std::nullopt;
    }
    const auto n = static_cast<long>(triangles.size());
    if (numVertices % p == 0 && n == 2L * p * (numVertices / p - 1)) {
        grid.rings = numVertices / p;
    } else if (numVertices % p == 1 && n == 2L * p * ((numVertices - 1) / p - 1) + p) {
        grid.rings = (numVertices - 1) / p;
        grid.apex = numVertices - 1;
    } else {
        return std::nullopt;
    }
    size_t t = 0;
    for (int i = 0; i + 1 < grid.rings; ++i) {
        for (int j = 0; j < p; ++j) {
            const int j1 = (j + 1) % p;
            const std::array<int, 3> first{i * p + j, i * p + j1, (i + 1) * p + j};
            const std::array<int, 3> second{i * p + j1, (i + 1) * p + j1, (i + 1) * p + j};
            if (triangles[t++] != first || triangles[t++] != second) {
                return std::nullopt;
            }
        }
    }
    if (grid.apex >= 0) {
        const int last = (grid.rings - 1) * p;
        for (int j = 0; j < p; ++j) {
            if (triangles[t++] != std::array<int, 3>{last + j, last + (j + 1) % p, grid.apex}) {
                return std::nullopt;
            }
        }
    }
    return grid;
}

TubeLevelsOfDetail::TubeLevelsOfDetail(const std::vector<std::array<int, 3>>& triangles,
                                       const Eigen::Matrix3Xd& rest)
    : m_grid(findTubeGrid(triangles, static_cast<int>(rest.cols())))
{
    m_indices.reserve(triangles.size() * 3);
    for (const auto& t : triangles) {
        for (int v : t) {
            m_indices.push_back(static_cast<std::uint32_t>(v));
        }
    }
    if (m_grid) {
        buildGridChunks(rest);
        return;
    }
    for (size_t first = 0; first < triangles.size(); first += kChunkTriangles) {
        const size_t last = std::min(triangles.size(), first + kChunkTriangles);
        Chunk chunk;
        chunk.vertices = uniqueVertices(triangles, first, last);
        chunk.ranges[0][0] = {static_cast<int>(first * 3), static_cast<int>((last - first) * 3)};
        m_chunks.push_back(std::move(chunk));
    }
}

int TubeLevelsOfDetail::vertex(int ring, int column) const
{
    return ring * m_grid->perRing + column % m_grid->perRing;
}

void TubeLevelsOfDetail::buildGridChunks(const Eigen::Matrix3Xd& rest)
{
    const int p = m_grid->perRing;
    const int bands = m_grid->rings - 1;
    for (int first = 0; first < bands; first += kBandsPerChunk) {
        Chunk chunk;
        const int last = std::min(bands, first + kBandsPerChunk);
        const int count = last - first;
        for (int level = 1; level <= kMaxLevel; ++level) {
            const int step = stepOf(level);
            if (count % step != 0 || p % step != 0 || p / step < kMinPerRing) {
                break;
            }
            chunk.maxLevel = level;
        }
        for (int ring = first; ring <= last; ++ring) {
            for (int j = 0; j < p; ++j) {
                chunk.vertices.push_back(vertex(ring, j));
            }
        }
        chunk.ranges[0][0] = {6 * p * first, 6 * p * count};
        for (int level = 1; level <= chunk.maxLevel; ++level) {
            const int step = stepOf(level);
            chunk.error[static_cast<size_t>(level)] = gridError(rest, first, last, step);
            for (int startLevel = 0; startLevel <= level; ++startLevel) {
                for (int endLevel = 0; endLevel <= level; ++endLevel) {
                    const auto begin = static_cast<int>(m_indices.size());
                    for (int a = first; a < last; a += step) {
                        const int b = a + step;
                        appendBand(a, a == first ? stepOf(startLevel) : step, b,
                                   b == last ? stepOf(endLevel) : step);
                    }
                    chunk.ranges[static_cast<size_t>(level)][variant(startLevel, endLevel)] = {
                        begin, static_cast<int>(m_indices.size()) - begin};
                }
            }
        }
        m_chunks.push_back(std::move(chunk));
    }
    if (m_grid->apex >= 0) {
        Chunk fan;
        const int last = (m_grid->rings - 1) * p;
        for (int j = 0; j < p; ++j) {
            fan.vertices.push_back(last + j);
        }
        fan.vertices.push_back(m_grid->apex);
        fan.ranges[0][0] = {6 * p * bands, 3 * p};
        m_chunks.push_back(std::move(fan));
    }
}

void TubeLevelsOfDetail::appendBand(int a, int stepA, int b, int stepB)
{
    // Zip the two rings along the angle: each triangle advances one ring by
    // one of its edges, the one whose next vertex comes first (ring a on a
    // tie, which reproduces the grid's own split of equal spacings).
    const int p = m_grid->perRing;
    const int countA = p / stepA;
    const int countB = p / stepB;
    int ia = 0;
    int ib = 0;
    const auto push = [this](int x, int y, int z) {
        m_indices.insert(m_indices.end(), {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                                           static_cast<std::uint32_t>(z)});
    };
    while (ia < countA || ib < countB) {
        const int nextA = ia < countA ? (ia + 1) * stepA : std::numeric_limits<int>::max();
        const int nextB = ib < countB ? (ib + 1) * stepB : std::numeric_limits<int>::max();
        if (nextA <= nextB) {
            push(vertex(a, ia * stepA), vertex(a, (ia + 1) * stepA), vertex(b, ib * stepB));
            ++ia;
        } else {
            push(vertex(a, ia * stepA), vertex(b, (ib + 1) * stepB), vertex(b, ib * stepB));
            ++ib;
        }
    }
}

double TubeLevelsOfDetail::gridError(const Eigen::Matrix3Xd& rest, int firstRing, int lastRing,
                                     int step) const
{
    const int p = m_grid->perRing;
    double worst = 0.0;
    for (int i = firstRing; i <= lastRing; ++i) {
        const int i0 = std::min(firstRing + (i - firstRing) / step * step, lastRing - step);
        const double u = static_cast<double>(i - i0) / step;
        for (int j = 0; j < p; ++j) {
            const int j0 = j / step * step;
            const double v = static_cast<double>(j - j0) / step;
            // The coarse quad's two triangles, split as the grid splits its own.
            const Eigen::Vector3d a0 = rest.col(vertex(i0, j0));
            const Eigen::Vector3d a1 = rest.col(vertex(i0, j0 + step));
            const Eigen::Vector3d b0 = rest.col(vertex(i0 + step, j0));
            const Eigen::Vector3d b1 = rest.col(vertex(i0 + step, j0 + step));
            const Eigen::Vector3d onCoarse =
                u + v <= 1.0 ? Eigen::Vector3d(a0 + v * (a1 - a0) + u * (b0 - a0))
                             : Eigen::Vector3d(b1 + (1.0 - v) * (b0 - b1) + (1.0 - u) * (a1 - b1));
            worst = std::max(worst, (rest.col(vertex(i, j)) - onCoarse).norm());
        }
    }
    return worst;
}

double TubeLevelsOfDetail::error(int c, int level) const
{
    return m_chunks[static_cast<size_t>(c)].error[static_cast<size_t>(level)];
}

TubeLevelsOfDetail::Range TubeLevelsOfDetail::range(int c, int level, int startLevel, int endLevel) const
{
    return m_chunks[static_cast<size_t>(c)].ranges[static_cast<size_t>(level)][variant(startLevel, endLevel)];
}

int TubeLevelsOfDetail::levelFor(int c, double nearest, double allowed) const
{
    const Chunk& chunk = m_chunks[static_cast<size_t>(c)];
    int level = 0;
    while (level < chunk.maxLevel && chunk.error[static_cast<size_t>(level + 1)] <= allowed * nearest) {
        ++level;
    }
    return level;
}

std::vector<TubeLevelsOfDetail::Range> TubeLevelsOfDetail::drawList(const std::vector<double>& nearest,
                                                                    double allowed) const
{
    const int n = numChunks();
    std::vector<int> levels(static_cast<size_t>(n), -1);
    for (int c = 0; c < n; ++c) {
        if (nearest[static_cast<size_t>(c)] >= 0.0) {
            levels[static_cast<size_t>(c)] = levelFor(c, nearest[static_cast<size_t>(c)], allowed);
        }
    }
    // A ring shared with a drawn neighbour is drawn at the finer level of
    // the two; the open first ring and a ring next to a culled chunk (which
    // lies wholly outside the image) at the chunk's own.
    const auto boundary = [&](int level, int neighbour) {
        if (neighbour < 0 || neighbour >= n || levels[static_cast<size_t>(neighbour)] < 0) {
            return level;
        }
        return std::min(level, levels[static_cast<size_t>(neighbour)]);
    };
    std::vector<Range> list;
    for (int c = 0; c < n; ++c) {
        const int level = levels[static_cast<size_t>(c)];
        if (level < 0) {
            continue;
        }
        const Range r = range(c, level, boundary(level, c - 1), boundary(level, c + 1));
        if (!list.empty() && list.back().first + list.back().count == r.first) {
            list.back().count += r.count;
        } else {
            list.push_back(r);
        }
    }
    return list;
}

}  // namespace colonosim::render
