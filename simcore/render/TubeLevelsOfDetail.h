#pragma once
/// \file
/// Levels of detail for a wall mesh laid out as a tube grid, and the chunks
/// the endoscope view culls by.
///
/// A tube grid (ProceduralColon's buildTube): R rings of P vertices, vertex
/// (i, j) at index i P + j, each band between rings i and i + 1 split into
/// the quads' two counter-clockwise triangles (i,j) (i,j+1) (i+1,j) and
/// (i,j+1) (i+1,j+1) (i+1,j), in band order, then optionally a fan of P
/// triangles closing ring R - 1 on one apex vertex. findTubeGrid() recognises
/// that layout from the triangles alone; any other mesh is drawn as it is,
/// in chunks of kChunkTriangles consecutive triangles.
///
/// Chunks of a grid are kBandsPerChunk bands (the fan is a chunk of its own,
/// drawn at full detail). Level L of a chunk keeps every 2^L-th ring and every
/// 2^L-th vertex round each ring (geometrical mipmapping, de Boer 2000), so
/// it draws 4^-L of the triangles. A ring a chunk shares with a neighbour is
/// drawn at the finer of the two levels, the band next to it zipped between
/// the two spacings (stitching), so neighbouring levels meet without cracks
/// (T-junctions): every edge of the drawn mesh is shared by two triangles of
/// opposite orientation, except those of an open end ring.
///
/// A level's geometric error (m, at rest) is the largest distance of a fine
/// vertex from the bilinear interpolation of the coarse grid round it. The
/// view draws each chunk at the coarsest level whose error, seen from the
/// chunk's nearest point, stays within the allowed error on the screen
/// (RenderParameters::levelOfDetailError pixels), so the picture differs from
/// the full mesh's by at most about that much wherever the wall is at rest.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace colonosim::render {

struct TubeGrid {
    int perRing = 0;  ///< P, vertices round each ring
    int rings = 0;    ///< R
    int apex = -1;    ///< the vertex closing the last ring, -1 when the end is open
};

/// The tube-grid layout of `triangles` over `numVertices` vertices, or
/// nothing when they are laid out otherwise.
[[nodiscard]] std::optional<TubeGrid> findTubeGrid(const std::vector<std::array<int, 3>>& triangles,
                                                   int numVertices);

class TubeLevelsOfDetail {
public:
    static constexpr int kBandsPerChunk = 16;
    static constexpr int kMaxLevel = 2;
    static constexpr int kMinPerRing = 12;        ///< the fewest vertices a coarse ring keeps
    static constexpr int kChunkTriangles = 2048;  ///< chunk size of a mesh that is no tube grid

    /// An index range of indices(): `count` indices from `first`.
    struct Range {
        int first = 0;
        int count = 0;
    };

    /// `rest`: the vertices at rest (m), one column per vertex.
    TubeLevelsOfDetail(const std::vector<std::array<int, 3>>& triangles, const Eigen::Matrix3Xd& rest);

    /// Every chunk's triangles at every level and stitching; the full mesh's
    /// triangles come first, in their own order.
    [[nodiscard]] const std::vector<std::uint32_t>& indices() const { return m_indices; }
    [[nodiscard]] const std::optional<TubeGrid>& grid() const { return m_grid; }
    [[nodiscard]] int numChunks() const { return static_cast<int>(m_chunks.size()); }
    /// The unique vertices of chunk c at full detail (for its bounds).
    [[nodiscard]] const std::vector<int>& chunkVertices(int c) const
    {
        return m_chunks[static_cast<size_t>(c)].vertices;
    }
    /// The coarsest level chunk c has (0: full detail only).
    [[nodiscard]] int maxLevel(int c) const { return m_chunks[static_cast<size_t>(c)].maxLevel; }
    /// The geometric error of chunk c at `level` (m, at rest; 0 at level 0).
    [[nodiscard]] double error(int c, int level) const;
    /// Chunk c at `level`, its first ring at `startLevel` and its last at
    /// `endLevel` (each at most `level`).
    [[nodiscard]] Range range(int c, int level, int startLevel, int endLevel) const;

    /// The ranges to draw, neighbouring ones merged. `nearest[c]`: the
    /// distance from the lens to the nearest point of chunk c (m, 0 when
    /// the lens is within it), negative for a chunk not drawn (culled).
    /// `allowed`: the geometric error allowed per metre of distance (the
    /// pixel angle times the allowed pixels; 0 draws everything at full
    /// detail).
    [[nodiscard]] std::vector<Range> drawList(const std::vector<double>& nearest, double allowed) const;
    /// The level drawList() gives a chunk at distance `nearest` (m).
    [[nodiscard]] int levelFor(int c, double nearest, double allowed) const;

private:
    struct Chunk {
        std::vector<int> vertices;
        int maxLevel = 0;
        std::array<double, kMaxLevel + 1> error{};
        /// Level L's ranges, (kMaxLevel + 1)^2 of them, by (startLevel, endLevel).
        std::array<std::array<Range, (kMaxLevel + 1) * (kMaxLevel + 1)>, kMaxLevel + 1> ranges{};
    };

    void buildGridChunks(const Eigen::Matrix3Xd& rest);
    /// Appends the band between ring a (every stepA-th vertex) and ring b.
    void appendBand(int a, int stepA, int b, int stepB);
    [[nodiscard]] double gridError(const Eigen::Matrix3Xd& rest, int firstRing, int lastRing, int step) const;
    [[nodiscard]] int vertex(int ring, int column) const;

    std::optional<TubeGrid> m_grid;
    std::vector<std::uint32_t> m_indices;
    std::vector<Chunk> m_chunks;
};

}  // namespace colonosim::render
