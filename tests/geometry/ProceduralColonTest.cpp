#include "simcore/geometry/ProceduralColon.h"

#include "MeshChecks.h"
#include "simcore/geometry/CentrelineSampling.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace colonosim::geometry {
namespace {

class ProceduralColon : public ::testing::Test {
protected:
    static void SetUpTestSuite() { s_anatomy = new ColonAnatomy(buildProceduralColon(AnatomyParameters{})); }
    static void TearDownTestSuite() { delete s_anatomy; }
    static const ColonAnatomy& anatomy() { return *s_anatomy; }
    static inline ColonAnatomy* s_anatomy = nullptr;
};

TEST_F(ProceduralColon, NodeCountsMatchThePaper)
{
    const int numPhysics = anatomy().physicsMesh.numVertices();
    const int numVisual = anatomy().visualMesh.numVertices();
    std::cout << "physics nodes " << numPhysics << ", triangles " << anatomy().physicsMesh.numTriangles()
              << "; visual vertices " << numVisual << ", triangles " << anatomy().visualMesh.numTriangles()
              << "\n";
    EXPECT_NEAR(numPhysics, 1900, 50);
    EXPECT_GE(numVisual, 50000);
    EXPECT_EQ(anatomy().physicsNodes.size(), static_cast<std::size_t>(numPhysics));
}

TEST_F(ProceduralColon, MeshesAreManifoldOrientedAndOpenOnlyAtTheAnus)
{
    const AnatomyParameters p;
    for (const auto* mesh : {&anatomy().physicsMesh, &anatomy().visualMesh}) {
        const testing::EdgeCounts counts = testing::countEdges(*mesh);
        EXPECT_EQ(counts.numNonManifoldEdges, 0);
        EXPECT_EQ(counts.numInconsistentEdges, 0);
        const int perRing = mesh == &anatomy().physicsMesh ? static_cast<int>(p.physicsNodesPerRing)
                                                           : static_cast<int>(p.visualNodesPerRing);
        EXPECT_EQ(counts.numBoundaryEdges, perRing) << "only the anal ring may be open";
    }
}

TEST_F(ProceduralColon, NormalsPointOutOfTheLumen)
{
    const TriangleMesh& mesh = anatomy().physicsMesh;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = mesh.vertices.col(t[0]);
        const Eigen::Vector3d normal = (mesh.vertices.col(t[1]) - a).cross(mesh.vertices.col(t[2]) - a);
        // Sum of each corner's offset from its own ring centre.
        Eigen::Vector3d radial = Eigen::Vector3d::Zero();
        for (int k : t) {
            radial += mesh.vertices.col(k) -
                      sampleCentreline(anatomy().centreline,
                                       anatomy().physicsNodes[static_cast<std::size_t>(k)].arcLength)
                          .point;
        }
        ASSERT_GT(normal.dot(radial), 0.0);
    }
}

TEST_F(ProceduralColon, AttachmentsAndMesenteryRoots)
{
    const AnatomyParameters p;
    const TriangleMesh& mesh = anatomy().physicsMesh;
    int numFixed = 0;
    for (std::size_t i = 0; i < anatomy().physicsNodes.size(); ++i) {
        const PhysicsNodeInfo& info = anatomy().physicsNodes[i];
        const Eigen::Vector3d rest = mesh.vertices.col(static_cast<Eigen::Index>(i));
        numFixed += info.attachment == Attachment::Fixed ? 1 : 0;
        if (info.arcLength < kAnalCanalLength) {
            EXPECT_EQ(info.attachment, Attachment::Fixed);
        }
        if (info.segment == Segment::Sigmoid || info.segment == Segment::Transverse) {
            EXPECT_EQ(info.attachment, Attachment::Mesenteric);
        }
        if (info.segment == Segment::Descending || info.segment == Segment::SplenicFlexure) {
            EXPECT_EQ(info.attachment, Attachment::Retroperitoneal);
        }
        if (info.attachment == Attachment::Mesenteric) {
            const double h = info.segment == Segment::Sigmoid      ? p.sigmoidMesenteryHeight
                             : info.segment == Segment::Transverse ? p.transverseMesenteryHeight
                                                                   : p.mobileColonMesenteryHeight;
            const double length = (info.mesenteryRoot - rest).norm();
            // Root is h + r posterior of the axis; the node lies on a circle of radius r around it.
            EXPECT_GE(length, h - 1e-9);
            EXPECT_LE(length, h + 2.0 * 0.5 * p.cecumDiameter + 1e-9);
            EXPECT_GT(info.mesenteryRoot.y(), rest.y() - 2.0 * 0.5 * p.cecumDiameter);
        } else {
            EXPECT_EQ((info.mesenteryRoot - rest).norm(), 0.0);
        }
    }
    EXPECT_EQ(numFixed, 2 * static_cast<int>(p.physicsNodesPerRing))
        << "the first two rings are in the anal canal";
}

struct MobilityCase {
    const char* name;
    double ascendingMobileFraction;
    double descendingMobile;
    bool expectMobileCecum;
    bool expectMobileAscendingTop;
    bool expectMobileDescending;
};

class Mobility : public ::testing::TestWithParam<MobilityCase> {};

TEST_P(Mobility, SegmentsHangWhereDeclared)
{
    AnatomyParameters p;
    p.ascendingMobileFraction = GetParam().ascendingMobileFraction;
    p.descendingMobile = GetParam().descendingMobile;
    p.visualRingCount = 100;  // the visual mesh is not under test
    const ColonAnatomy a = buildProceduralColon(p);
    bool cecum = false;
    bool ascendingTop = false;
    bool descending = false;
    const double ascendingStart = p.rectumLength + p.sigmoidLength + p.descendingLength +
                                  p.splenicFlexureLength + p.transverseLength + p.hepaticFlexureLength;
    for (const PhysicsNodeInfo& info : a.physicsNodes) {
        const bool mobile = info.attachment == Attachment::Mesenteric;
        if (info.segment == Segment::Cecum)
            cecum |= mobile;
        if (info.segment == Segment::Descending)
            descending |= mobile;
        if (info.segment == Segment::Ascending && info.arcLength < ascendingStart + 0.03)
            ascendingTop |= mobile;
    }
    EXPECT_EQ(cecum, GetParam().expectMobileCecum);
    EXPECT_EQ(ascendingTop, GetParam().expectMobileAscendingTop);
    EXPECT_EQ(descending, GetParam().expectMobileDescending);
}

INSTANTIATE_TEST_SUITE_P(Cases, Mobility,
                         ::testing::Values(MobilityCase{"fixedRightColon", 0.0, 0.0, false, false, false},
                                           MobilityCase{"halfMobile", 0.5, 0.0, true, false, false},
                                           MobilityCase{"fullyMobile", 1.0, 1.0, true, true, true}),
                         [](const auto& info) { return std::string(info.param.name); });

// anatomy.sigmoidRootLength: the whole mobile sigmoid hangs from one root
// line that long; every other node keeps the root it has by default.
TEST(SigmoidRoot, TheSigmoidHangsFromOneLineOfTheDeclaredLength)
{
    AnatomyParameters perRing;
    perRing.sigmoidLength = 0.66;
    AnatomyParameters narrow = perRing;
    narrow.sigmoidRootLength = 0.17;
    const ColonAnatomy a = buildProceduralColon(perRing);
    const ColonAnatomy b = buildProceduralColon(narrow);
    ASSERT_EQ(a.physicsNodes.size(), b.physicsNodes.size());
    Eigen::Vector3d lo = Eigen::Vector3d::Zero();
    Eigen::Vector3d hi = Eigen::Vector3d::Zero();
    double spread = -1.0;
    int sigmoidNodes = 0;
    for (size_t i = 0; i < b.physicsNodes.size(); ++i) {
        const PhysicsNodeInfo& info = b.physicsNodes[i];
        if (info.segment != Segment::Sigmoid || info.attachment != Attachment::Mesenteric) {
            EXPECT_EQ((info.mesenteryRoot - a.physicsNodes[i].mesenteryRoot).norm(), 0.0) << "node " << i;
            continue;
        }
        ++sigmoidNodes;
        // The two roots furthest apart span the line.
        for (size_t j = 0; j < i; ++j) {
            const PhysicsNodeInfo& other = b.physicsNodes[j];
            if (other.segment == Segment::Sigmoid && other.attachment == Attachment::Mesenteric &&
                (info.mesenteryRoot - other.mesenteryRoot).norm() > spread) {
                spread = (info.mesenteryRoot - other.mesenteryRoot).norm();
                lo = other.mesenteryRoot;
                hi = info.mesenteryRoot;
            }
        }
        const Eigen::Vector3d rest = b.physicsMesh.vertices.col(static_cast<Eigen::Index>(i));
        EXPECT_GT((info.mesenteryRoot - rest).norm(), 0.0) << "a tether of length 0 at node " << i;
    }
    ASSERT_GT(sigmoidNodes, 100);
    EXPECT_NEAR(spread, 0.17, 1e-9) << "the line's ends are the roots of the sigmoid's two ends";
    const Eigen::Vector3d along = (hi - lo).normalized();
    for (const PhysicsNodeInfo& info : b.physicsNodes) {
        if (info.segment == Segment::Sigmoid && info.attachment == Attachment::Mesenteric) {
            const Eigen::Vector3d r = info.mesenteryRoot - lo;
            EXPECT_LT((r - r.dot(along) * along).norm(), 1e-12) << "every root on the one line";
        }
    }
    AnatomyParameters tooLong = perRing;
    tooLong.sigmoidRootLength = 0.31;
    EXPECT_THROW(tooLong.validate(), params::ParameterError);
}

TEST_F(ProceduralColon, LandmarksSitInTheCecum)
{
    ASSERT_EQ(anatomy().landmarks.size(), 2u);
    for (const Landmark& l : anatomy().landmarks) {
        ASSERT_GE(l.nearestPhysicsNode, 0);
        const PhysicsNodeInfo& node = anatomy().physicsNodes[static_cast<std::size_t>(l.nearestPhysicsNode)];
        EXPECT_TRUE(node.segment == Segment::Cecum || node.segment == Segment::Ascending) << l.name;
        const double gap = (anatomy().physicsMesh.vertices.col(l.nearestPhysicsNode) - l.position).norm();
        EXPECT_LT(gap, 0.02) << l.name << ": nearest node within one ring spacing";
        EXPECT_NEAR(l.normal.norm(), 1.0, 1e-12);
    }
    const Landmark& valve = anatomy().landmarks[0];
    EXPECT_EQ(valve.name, "ileocecal_valve");
    EXPECT_LT(valve.normal.x(), 0.0)
        << "the valve is on the medial (left, +x) wall, so its inward normal points right";
}

TEST_F(ProceduralColon, NoRestNodePenetratesAnyOrgan)
{
    ASSERT_GE(anatomy().organs.size(), 7u);
    for (const ImplicitShape& organ : anatomy().organs) {
        for (const auto* mesh : {&anatomy().physicsMesh, &anatomy().visualMesh}) {
            double worst = 0.0;
            for (Eigen::Index i = 0; i < mesh->vertices.cols(); ++i) {
                worst = std::max(worst, organ.penetration(mesh->vertices.col(i), nullptr));
            }
            EXPECT_EQ(worst, 0.0) << organ.name;
        }
    }
}

}  // namespace
}  // namespace colonosim::geometry
