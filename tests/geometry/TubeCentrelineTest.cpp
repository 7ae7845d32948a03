#include "simcore/geometry/TubeCentreline.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/MeshExport.h"
#include "simcore/geometry/MeshImport.h"
#include "simcore/geometry/ProceduralColon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <string>

namespace colonosim::geometry {
namespace {

/// Nearest point of `p` on the polyline `points`: distance and arc length.
struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    double arcLength = 0.0;
};

Nearest nearestOn(const Centreline& c, const Eigen::Vector3d& p)
{
    Nearest best;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
        const Eigen::Vector3d d = c.points[i + 1] - c.points[i];
        const double len2 = d.squaredNorm();
        const double u = len2 > 0.0 ? std::clamp((p - c.points[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
        const double dist = (c.points[i] + u * d - p).norm();
        if (dist < best.distance)
            best = {dist, c.arcLength[i] + u * (c.arcLength[i + 1] - c.arcLength[i])};
    }
    return best;
}

double radiusAt(const Centreline& c, double s)
{
    const auto it = std::lower_bound(c.arcLength.begin(), c.arcLength.end(), s);
    const auto i =
        static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(it - c.arcLength.begin(), 0, c.numPoints() - 1));
    return c.radius[i];
}

/// Whether a mesh with rings `ringSpacing` apart resolves the true
/// centreline near `s`: within 1.5 ring spacings of `s` it nowhere turns by
/// 0.5 rad or more over one ring spacing (bend radius < 2 ring spacings).
/// (The laid-out colon bends no tighter than twice its lumen radius, so the
/// 14 mm rings of the physics mesh resolve it everywhere.)
bool resolved(const Centreline& c, double s, double ringSpacing)
{
    for (int k = -3; k <= 3; ++k) {
        const double x = s + 0.5 * k * ringSpacing;
        const CentrelineSample a = sampleCentreline(c, x - 0.5 * ringSpacing);
        const CentrelineSample b = sampleCentreline(c, x + 0.5 * ringSpacing);
        if (std::acos(std::clamp(a.tangent.dot(b.tangent), -1.0, 1.0)) >= 0.5)
            return false;
    }
    return true;
}

struct Comparison {
    double worstComputed = 0.0;  ///< max over computed points of distance / tolerance
    double worstTrue = 0.0;      ///< max over true points of distance / tolerance
    double worstInRadii = 0.0;   ///< max over both of distance / local true radius
    double worstJump = 0.0;      ///< largest step of the nearest true arc length between neighbours, m
    int numUnresolved = 0;       ///< computed points near a kink the mesh does not resolve (expected none)
};

/// Tolerance: a quarter of the local lumen radius everywhere.
Comparison compare(const Centreline& computed, const Centreline& truth, double ringSpacing)
{
    Comparison result;
    const auto tolerance = [&](double s, bool* isResolved) {
        *isResolved = resolved(truth, s, ringSpacing);
        return 0.25 * radiusAt(truth, s);
    };
    double previous = -1.0;
    for (const Eigen::Vector3d& p : computed.points) {
        const Nearest n = nearestOn(truth, p);
        bool isResolved = true;
        result.worstComputed =
            std::max(result.worstComputed, n.distance / tolerance(n.arcLength, &isResolved));
        result.worstInRadii = std::max(result.worstInRadii, n.distance / radiusAt(truth, n.arcLength));
        if (!isResolved)
            ++result.numUnresolved;
        if (previous >= 0.0)
            result.worstJump = std::max(result.worstJump, std::abs(n.arcLength - previous));
        previous = n.arcLength;
    }
    for (int i = 0; i < truth.numPoints(); ++i) {
        const Nearest n = nearestOn(computed, truth.points[static_cast<std::size_t>(i)]);
        bool isResolved = true;
        const double s = truth.arcLength[static_cast<std::size_t>(i)];
        result.worstTrue = std::max(result.worstTrue, n.distance / tolerance(s, &isResolved));
        result.worstInRadii =
            std::max(result.worstInRadii, n.distance / truth.radius[static_cast<std::size_t>(i)]);
    }
    return result;
}

void expectMatchesTruth(const TriangleMesh& mesh, const Centreline& truth, double ringSpacing,
                        const char* name)
{
    const auto start = std::chrono::steady_clock::now();
    const Centreline c = computeCentreline(mesh);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_GE(c.numPoints(), 2);
    const Comparison d = compare(c, truth, ringSpacing);
    const double frontError = (c.points.front() - truth.points.front()).norm() / truth.radius.front();
    const double backError = (c.points.back() - truth.points.back()).norm() / truth.radius.back();
    std::cout << name << " (" << mesh.numVertices() << " vertices, " << mesh.numTriangles()
              << " faces): " << seconds << " s, length " << c.length() << " vs " << truth.length()
              << " m; deviation / tolerance: computed->true " << d.worstComputed << ", true->computed "
              << d.worstTrue << "; worst deviation " << d.worstInRadii << " local radii (" << d.numUnresolved
              << " of " << c.numPoints() << " points at unresolved kinks); ends " << frontError << " / "
              << backError << " radii; largest jump " << d.worstJump << " m; radius at the middle "
              << c.radius[c.radius.size() / 2] << " vs " << radiusAt(truth, 0.5 * truth.length()) << " m\n";
    EXPECT_NEAR(c.length(), truth.length(), 0.03 * truth.length());
    EXPECT_LT(d.worstComputed, 1.0) << "every computed point lies near the true centreline";
    EXPECT_LT(d.worstTrue, 1.0) << "every true point lies near the computed centreline";
    EXPECT_EQ(d.numUnresolved, 0) << "the mesh resolves every bend of the centreline";
    EXPECT_LT(d.worstJump, 0.05) << "the computed centreline never jumps to another part of the colon";
    EXPECT_LT(frontError, 0.25) << "starts at the anus (the open boundary loop)";
    EXPECT_LT(backError, 0.25) << "ends at the cecal base, not on the cap";
    for (double r : c.radius)
        EXPECT_GT(r, 0.0);
    const double midRadius = c.radius[c.radius.size() / 2];
    EXPECT_NEAR(midRadius, radiusAt(truth, 0.5 * truth.length()), 0.15 * midRadius);
}

double ringSpacing(const ColonAnatomy& anatomy, double numRings)
{
    return anatomy.centreline.length() / (numRings - 1.0);
}

class FullColon : public ::testing::Test {
protected:
    static void SetUpTestSuite() { anatomy_ = new ColonAnatomy(buildProceduralColon(AnatomyParameters{})); }
    static void TearDownTestSuite()
    {
        delete anatomy_;
        anatomy_ = nullptr;
    }
    static ColonAnatomy* anatomy_;
};

ColonAnatomy* FullColon::anatomy_ = nullptr;

TEST_F(FullColon, PhysicsMeshCentrelineFollowsTheTrueOne)
{
    const double rings =
        (anatomy_->physicsMesh.numVertices() - 1) / AnatomyParameters{}.physicsNodesPerRing - 1.0;
    expectMatchesTruth(anatomy_->physicsMesh, anatomy_->centreline, ringSpacing(*anatomy_, rings),
                       "physics mesh");
}

TEST_F(FullColon, VisualMeshCentrelineFollowsTheTrueOneInUnderASecond)
{
    expectMatchesTruth(anatomy_->visualMesh, anatomy_->centreline,
                       ringSpacing(*anatomy_, AnatomyParameters{}.visualRingCount), "visual mesh");
}

TEST_F(FullColon, ImportedPhysicsMeshCentrelineFollowsTheTrueOne)
{
    std::random_device random;
    const auto dir =
        std::filesystem::temp_directory_path() / ("colonosim_centreline_" + std::to_string(random()));
    std::filesystem::create_directories(dir);
    const auto path = dir / "colon_physics.ply";
    writePly(path, anatomy_->physicsMesh, MeshEncoding::Binary);
    const ImportedMesh imported = importMesh(path);
    std::filesystem::remove_all(dir);
    EXPECT_EQ(imported.report.numOpenEnds, 1) << "open at the anus, closed at the cecum";
    const double rings = (imported.mesh.numVertices() - 1) / AnatomyParameters{}.physicsNodesPerRing - 1.0;
    expectMatchesTruth(imported.mesh, anatomy_->centreline, ringSpacing(*anatomy_, rings),
                       "imported physics mesh");
}

}  // namespace
}  // namespace colonosim::geometry
