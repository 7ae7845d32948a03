// Levels of detail of a tube-grid wall mesh: the layout is recognised, every
// mix of levels meets without cracks, and the errors are the geometry's.

#include "simcore/render/TubeLevelsOfDetail.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <utility>

namespace {

using colonosim::render::findTubeGrid;
using colonosim::render::TubeLevelsOfDetail;

struct Mesh {
    Eigen::Matrix3Xd vertices;
    std::vector<std::array<int, 3>> triangles;
};

/// A tube along +z laid out as ProceduralColon lays its own: `rings` rings
/// of `perRing` vertices 2 mm apart, radius 25 mm + fold * cos(ring / 4),
/// closed by an apex 1 cm beyond the last ring when `closed`.
Mesh makeTube(int perRing, int rings, bool closed, double fold = 0.0)
{
    Mesh mesh;
    mesh.vertices.resize(3, rings * perRing + (closed ? 1 : 0));
    for (int i = 0; i < rings; ++i) {
        const double r = 0.025 + fold * std::cos(i / 4.0);
        for (int j = 0; j < perRing; ++j) {
            const double theta = 2.0 * std::numbers::pi * j / perRing;
            mesh.vertices.col(i * perRing + j) =
                Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), 0.002 * i);
        }
    }
    for (int i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j < perRing; ++j) {
            const int j1 = (j + 1) % perRing;
            mesh.triangles.push_back({i * perRing + j, i * perRing + j1, (i + 1) * perRing + j});
            mesh.triangles.push_back({i * perRing + j1, (i + 1) * perRing + j1, (i + 1) * perRing + j});
        }
    }
    if (closed) {
        const int apex = rings * perRing;
        mesh.vertices.col(apex) = Eigen::Vector3d(0.0, 0.0, 0.002 * (rings - 1) + 0.01);
        const int last = (rings - 1) * perRing;
        for (int j = 0; j < perRing; ++j) {
            mesh.triangles.push_back({last + j, last + (j + 1) % perRing, apex});
        }
    }
    return mesh;
}

using Triangles = std::vector<std::array<int, 3>>;

Triangles drawn(const TubeLevelsOfDetail& levels, const std::vector<TubeLevelsOfDetail::Range>& list)
{
    Triangles triangles;
    for (const auto& range : list) {
        for (int k = range.first; k < range.first + range.count; k += 3) {
            const auto& idx = levels.indices();
            triangles.push_back({static_cast<int>(idx[static_cast<size_t>(k)]),
                                 static_cast<int>(idx[static_cast<size_t>(k + 1)]),
                                 static_cast<int>(idx[static_cast<size_t>(k + 2)])});
        }
    }
    return triangles;
}

/// The directed edges of `triangles`, each counted.
std::map<std::pair<int, int>, int> directedEdges(const Triangles& triangles)
{
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            ++edges[{t[static_cast<size_t>(k)], t[static_cast<size_t>((k + 1) % 3)]}];
        }
    }
    return edges;
}

double area(const Eigen::Matrix3Xd& v, const Triangles& triangles)
{
    double sum = 0.0;
    for (const auto& t : triangles) {
        sum += 0.5 * (v.col(t[1]) - v.col(t[0])).cross(v.col(t[2]) - v.col(t[0])).norm();
    }
    return sum;
}

TEST(TubeLevelsOfDetail, RecognisesATubeGridAndNothingElse)
{
    const Mesh closed = makeTube(48, 41, true);
    const auto grid = findTubeGrid(closed.triangles, static_cast<int>(closed.vertices.cols()));
    ASSERT_TRUE(grid.has_value());
    EXPECT_EQ(grid->perRing, 48);
    EXPECT_EQ(grid->rings, 41);
    EXPECT_EQ(grid->apex, 41 * 48);

    const Mesh open = makeTube(48, 41, false);
    const auto openGrid = findTubeGrid(open.triangles, static_cast<int>(open.vertices.cols()));
    ASSERT_TRUE(openGrid.has_value());
    EXPECT_EQ(openGrid->apex, -1);

    Mesh flipped = closed;
    std::swap(flipped.triangles[700][1], flipped.triangles[700][2]);
    EXPECT_FALSE(findTubeGrid(flipped.triangles, static_cast<int>(flipped.vertices.cols())).has_value());
    EXPECT_FALSE(findTubeGrid(closed.triangles, static_cast<int>(closed.vertices.cols()) + 1).has_value());
    Mesh shorter = closed;
    shorter.triangles.pop_back();
    EXPECT_FALSE(findTubeGrid(shorter.triangles, static_cast<int>(shorter.vertices.cols())).has_value());
}

TEST(TubeLevelsOfDetail, AMeshThatIsNoTubeIsDrawnWholeInChunksOfConsecutiveTriangles)
{
    Mesh mesh = makeTube(48, 61, true);
    std::swap(mesh.triangles[0], mesh.triangles[1]);
    const TubeLevelsOfDetail levels(mesh.triangles, mesh.vertices);
    EXPECT_FALSE(levels.grid().has_value());
    const int n = static_cast<int>(mesh.triangles.size());
    ASSERT_EQ(levels.numChunks(),
              (n + TubeLevelsOfDetail::kChunkTriangles - 1) / TubeLevelsOfDetail::kChunkTriangles);
    const std::vector<double> far(static_cast<size_t>(levels.numChunks()), 10.0);
    const auto list = levels.drawList(far, 1.0);
    ASSERT_EQ(list.size(), 1U);
    EXPECT_EQ(drawn(levels, list), mesh.triangles);
}

TEST(TubeLevelsOfDetail, FullDetailDrawsTheMeshAsItIs)
{
    const Mesh mesh = makeTube(48, 16 * 5 + 9, true, 0.003);
    const TubeLevelsOfDetail levels(mesh.triangles, mesh.vertices);
    ASSERT_TRUE(levels.grid().has_value());
    EXPECT_EQ(levels.numChunks(), 7);  // 5 whole chunks, one of 8 bands, the apex fan
    const std::vector<double> far(static_cast<size_t>(levels.numChunks()), 10.0);
    EXPECT_EQ(drawn(levels, levels.drawList(far, 0.0)), mesh.triangles);
    const std::vector<double> near(static_cast<size_t>(levels.numChunks()), 0.0);
    EXPECT_EQ(drawn(levels, levels.drawList(near, 1.0)), mesh.triangles);
}

TEST(TubeLevelsOfDetail, TheErrorOfAStraightCylinderIsTheSagittaOfItsCoarserChords)
{
    const int perRing = 48;
    const Mesh mesh = makeTube(perRing, 33, false);
    const TubeLevelsOfDetail levels(mesh.triangles, mesh.vertices);
    ASSERT_EQ(levels.maxLevel(0), 2);
    const double r = 0.025;
    EXPECT_NEAR(levels.error(0, 1), r * (1.0 - std::cos(2.0 * std::numbers::pi / perRing)), 1e-12);
    EXPECT_NEAR(levels.error(0, 2), r * (1.0 - std::cos(4.0 * std::numbers::pi / perRing)), 1e-12);
    EXPECT_EQ(levels.error(0, 0), 0.0);
    // Farther means coarser, and the level is the coarsest whose error fits.
    const double allowed = 0.01;  // 1 cm of error per metre
    EXPECT_EQ(levels.levelFor(0, 0.0, allowed), 0);
    EXPECT_EQ(levels.levelFor(0, 0.99 * levels.error(0, 1) / allowed, allowed), 0);
    EXPECT_EQ(levels.levelFor(0, 1.01 * levels.error(0, 1) / allowed, allowed), 1);
    EXPECT_EQ(levels.levelFor(0, 1.01 * levels.error(0, 2) / allowed, allowed), 2);
    EXPECT_EQ(levels.levelFor(0, 100.0, allowed), 2);
}

TEST(TubeLevelsOfDetail, EveryMixOfLevelsMeetsWithoutCracks)
{
    // Folds make the levels' errors differ, so distances pick each level.
    const int perRing = 48;
    const Mesh mesh = makeTube(perRing, 16 * 6 + 1, true, 0.003);
    const TubeLevelsOfDetail levels(mesh.triangles, mesh.vertices);
    const int n = levels.numChunks();
    ASSERT_EQ(n, 7);
    const double fullArea = area(mesh.vertices, mesh.triangles);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> pick(-1, 2);
    int mixes = 0;
    int coarser = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::vector<double> nearest(static_cast<size_t>(n));
        std::vector<int> wanted(static_cast<size_t>(n));
        std::set<int> culledRings;
        for (int c = 0; c < n; ++c) {
            int level = pick(random);
            level = std::min(level, levels.maxLevel(c));
            wanted[static_cast<size_t>(c)] = level;
            // A distance that selects exactly `level` at 1 m of error per metre.
            double d = -1.0;
            if (level == 0) {
                d = 0.0;
            } else if (level == 1) {
                d = 0.5 * (levels.error(c, 1) + levels.error(c, 2));
            } else if (level == 2) {
                d = 2.0 * levels.error(c, 2);
            }
            nearest[static_cast<size_t>(c)] = d;
            if (level < 0) {
                const int first = 16 * c;
                culledRings.insert({first, first + 16});
            }
        }
        for (int c = 0; c < n; ++c) {
            if (wanted[static_cast<size_t>(c)] >= 0) {
                ASSERT_EQ(levels.levelFor(c, nearest[static_cast<size_t>(c)], 1.0),
                          wanted[static_cast<size_t>(c)]);
            }
        }
        const Triangles triangles = drawn(levels, levels.drawList(nearest, 1.0));
        const auto edges = directedEdges(triangles);
        for (const auto& [edge, count] : edges) {
            ASSERT_EQ(count, 1) << "trial " << trial << ": edge " << edge.first << "-" << edge.second
                                << " drawn twice the same way";
            if (edges.count({edge.second, edge.first}) == 0) {
                // Only the open first ring and rings next to a culled chunk
                // may be bare.
                const int ringA = edge.first / perRing;
                const int ringB = edge.second / perRing;
                ASSERT_EQ(ringA, ringB) << "trial " << trial << ": a crack across rings";
                ASSERT_TRUE(ringA == 0 || culledRings.count(ringA) > 0)
                    << "trial " << trial << ": a crack on ring " << ringA;
            }
        }
        if (culledRings.empty()) {
            ++mixes;
            const double drawnArea = area(mesh.vertices, triangles);
            EXPECT_NEAR(drawnArea, fullArea, 0.02 * fullArea) << "trial " << trial;
            coarser += triangles.size() < mesh.triangles.size() ? 1 : 0;
        }
    }
    EXPECT_GT(mixes, 20);
    EXPECT_GT(coarser, 20);
}

TEST(TubeLevelsOfDetail, ACoarserLevelDrawsAQuarterOfTheTriangles)
{
    const Mesh mesh = makeTube(64, 16 * 4 + 1, false, 0.003);
    const TubeLevelsOfDetail levels(mesh.triangles, mesh.vertices);
    ASSERT_EQ(levels.numChunks(), 4);
    // Interior chunks with both neighbours at their own level: exact quarters.
    EXPECT_EQ(levels.range(1, 0, 0, 0).count, 3 * 2 * 64 * 16);
    EXPECT_EQ(levels.range(1, 1, 1, 1).count, 3 * 2 * 32 * 8);
    EXPECT_EQ(levels.range(1, 2, 2, 2).count, 3 * 2 * 16 * 4);
    // Stitching to a full-detail neighbour adds the finer ring's vertices.
    EXPECT_EQ(levels.range(1, 2, 0, 2).count, 3 * (2 * 16 * 3 + (64 + 16)));
}

}  // namespace
