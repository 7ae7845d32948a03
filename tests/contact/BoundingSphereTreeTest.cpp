// The bounding-sphere tree: refit keeps the spheres bounding after
// deformation, queries agree with brute force, disabled subtrees are skipped.

#include "simcore/contact/BoundingSphereTree.h"
#include "simcore/contact/SegmentTriangle.h"
#include "simcore/physics/SpringCalibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace colonosim::contact {
namespace {

/// Containment tolerance: rounding of a few sums of metre-scale doubles.
constexpr double kTolerance = 1e-12;

geometry::TriangleMesh tube()
{
    physics::TubeResolution resolution;  // 16 x 30 nodes, radius 20 mm
    return physics::makeStraightTube(resolution);
}

Eigen::Matrix3Xd deformed(const Eigen::Matrix3Xd& x, unsigned seed, double amplitude)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    Eigen::Matrix3Xd y = x;
    for (int i = 0; i < y.cols(); ++i) {
        y.col(i) += Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
    return y;
}

void expectBounding(const BoundingSphereTree& tree, const Eigen::Matrix3Xd& x)
{
    for (int i = 0; i < tree.numNodes(); ++i) {
        const auto& n = tree.node(i);
        if (n.triangle >= 0) {
            for (int v : tree.triangles()[static_cast<size_t>(n.triangle)]) {
                EXPECT_LE((x.col(v) - n.centre).norm(), n.radius + kTolerance) << "leaf " << i;
            }
        } else {
            for (int child : {n.left, n.right}) {
                const auto& c = tree.node(child);
                EXPECT_LE((c.centre - n.centre).norm() + c.radius, n.radius + kTolerance) << "node " << i;
            }
        }
    }
}

TEST(BoundingSphereTree, OneLeafPerTriangleAndBalanced)
{
    const geometry::TriangleMesh mesh = tube();
    const BoundingSphereTree tree(mesh.vertices, mesh.triangles);
    EXPECT_EQ(tree.numNodes(), 2 * mesh.numTriangles() - 1);
    for (int t = 0; t < mesh.numTriangles(); ++t) {
        EXPECT_EQ(tree.node(tree.leafOf(t)).triangle, t);
    }
    expectBounding(tree, mesh.vertices);
}

TEST(BoundingSphereTree, RefitBoundsAfterRandomDeformation)
{
    const geometry::TriangleMesh mesh = tube();
    BoundingSphereTree tree(mesh.vertices, mesh.triangles);
    for (unsigned seed = 1; seed <= 5; ++seed) {
        // Up to 3 cm of displacement: larger than the 14 mm rings, so the topology is badly out of date.
        const Eigen::Matrix3Xd x = deformed(mesh.vertices, seed, 0.01 * seed);
        tree.refit(x);
        expectBounding(tree, x);
    }
}

struct QueryCase {
    unsigned seed;
    double radius;  ///< m
};

class TreeQuery : public ::testing::TestWithParam<QueryCase> {};

TEST_P(TreeQuery, EqualsBruteForce)
{
    const geometry::TriangleMesh mesh = tube();
    const Eigen::Matrix3Xd x = deformed(mesh.vertices, GetParam().seed, 0.004);
    BoundingSphereTree tree(mesh.vertices, mesh.triangles);
    tree.refit(x);
    std::mt19937 rng(GetParam().seed + 100);
    std::uniform_real_distribution<double> across(-0.03, 0.03);
    std::uniform_real_distribution<double> along(-0.02, 0.43);
    const double r = GetParam().radius;
    for (int q = 0; q < 50; ++q) {
        const Eigen::Vector3d p0(across(rng), across(rng), along(rng));
        const Eigen::Vector3d p1 = p0 + Eigen::Vector3d(across(rng), across(rng), across(rng));
        std::vector<int> found;
        tree.queryCapsule(p0, p1, r, found);
        std::sort(found.begin(), found.end());
        std::vector<int> spheres;  // brute force over the leaf spheres: must be identical
        for (int t = 0; t < mesh.numTriangles(); ++t) {
            const auto& leaf = tree.node(tree.leafOf(t));
            if (squaredDistancePointSegment(leaf.centre, p0, p1) <= (leaf.radius + r) * (leaf.radius + r)) {
                spheres.push_back(t);
            }
        }
        EXPECT_EQ(found, spheres);
        // Every triangle truly within r of the segment is found (exact distance, unsigned).
        for (int t = 0; t < mesh.numTriangles(); ++t) {
            const auto& v = mesh.triangles[static_cast<size_t>(t)];
            double d2 = closestSegmentSegment(p0, p1, x.col(v[0]), x.col(v[1])).squaredDistance;
            d2 = std::min(d2, closestSegmentSegment(p0, p1, x.col(v[1]), x.col(v[2])).squaredDistance);
            d2 = std::min(d2, closestSegmentSegment(p0, p1, x.col(v[2]), x.col(v[0])).squaredDistance);
            if (d2 < r * r) {
                EXPECT_TRUE(std::binary_search(found.begin(), found.end(), t)) << "triangle " << t;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(RandomCapsules, TreeQuery,
                         ::testing::Values(QueryCase{1, 0.0}, QueryCase{2, 0.002}, QueryCase{3, 0.0065},
                                           QueryCase{4, 0.02}, QueryCase{5, 0.1}));

TEST(BoundingSphereTree, DisabledSubtreesAreNeverVisited)
{
    const geometry::TriangleMesh mesh = tube();
    BoundingSphereTree tree(mesh.vertices, mesh.triangles);
    // Awake: the nodes of the first 6 rings (z < 8 cm), as an active region would be.
    std::vector<std::uint8_t> awake(static_cast<size_t>(mesh.numVertices()));
    for (int i = 0; i < mesh.numVertices(); ++i) {
        awake[static_cast<size_t>(i)] = mesh.vertices(2, i) < 0.08 ? 1 : 0;
    }
    tree.setEnabledFromNodes(awake);
    int expectedEnabled = 0;
    for (const auto& tri : mesh.triangles) {
        expectedEnabled += (awake[static_cast<size_t>(tri[0])] | awake[static_cast<size_t>(tri[1])] |
                            awake[static_cast<size_t>(tri[2])]) != 0;
    }
    EXPECT_EQ(tree.numEnabledTriangles(), expectedEnabled);
    for (int i = 0; i < tree.numNodes(); ++i) {
        const auto& n = tree.node(i);
        if (n.left >= 0) {
            EXPECT_EQ(n.enabled, tree.node(n.left).enabled | tree.node(n.right).enabled);
        }
    }
    for (double z : {0.02, 0.07, 0.2, 0.4}) {
        std::vector<int> found;
        std::vector<int> visited;
        const int visits =
            tree.queryCapsule({0.0, 0.0, z - 0.03}, {0.0, 0.0, z + 0.03}, 0.03, found, &visited);
        EXPECT_EQ(visits, static_cast<int>(visited.size()));
        for (int i : visited) {
            EXPECT_TRUE(tree.node(i).enabled) << "visited disabled node " << i;
        }
        for (int t : found) {
            EXPECT_TRUE(tree.node(tree.leafOf(t)).enabled);
        }
        if (z > 0.15) {
            EXPECT_TRUE(found.empty());
            EXPECT_LT(visits, 10) << "a query in the sleeping part stops near the root";
        }
    }
    tree.enableAll();
    EXPECT_EQ(tree.numEnabledTriangles(), mesh.numTriangles());
}

}  // namespace
}  // namespace colonosim::contact
