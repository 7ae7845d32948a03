#include "simcore/geometry/MeshMapping.h"

#include "simcore/geometry/ProceduralColon.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

namespace colonosim::geometry {
namespace {

class MeshMappingOnColon : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_anatomy = new ColonAnatomy(buildProceduralColon(AnatomyParameters{}));
        const auto start = std::chrono::steady_clock::now();
        s_mapping = new MeshMapping(s_anatomy->physicsMesh, s_anatomy->visualMesh.vertices);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "mapping build: " << seconds * 1e3 << " ms for " << s_mapping->numVisualVertices()
                  << " vertices\n";
    }
    static void TearDownTestSuite()
    {
        delete s_mapping;
        delete s_anatomy;
    }
    static inline ColonAnatomy* s_anatomy = nullptr;
    static inline MeshMapping* s_mapping = nullptr;
};

TEST_F(MeshMappingOnColon, RestRoundTripIsExact)
{
    Eigen::Matrix3Xd mapped;
    s_mapping->apply(s_anatomy->physicsMesh.vertices, mapped);
    const double maxError = (mapped - s_anatomy->visualMesh.vertices).colwise().norm().maxCoeff();
    std::cout << "rest round-trip max error: " << maxError << " m\n";
    // Newton is run to 1e-14 m; 1e-9 m leaves room for rounding in apply().
    EXPECT_LT(maxError, 1e-9);
    // Every binding lies inside its triangle, or within 1% of it where the
    // smooth normal of no nearby triangle reaches the vertex from inside.
    double worstWeight = 0.0;
    for (const auto& b : s_mapping->bindings()) {
        worstWeight = std::min(worstWeight, b.weight.minCoeff());
    }
    std::cout << "most negative barycentric weight: " << worstWeight << "\n";
    EXPECT_GT(worstWeight, -0.01);
}

TEST_F(MeshMappingOnColon, RigidMotionMovesVerticesRigidly)
{
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Vector3d translation(0.05, -0.2, 0.1);
    const Eigen::Matrix3Xd moved = (rotation * s_anatomy->physicsMesh.vertices).colwise() + translation;
    Eigen::Matrix3Xd mapped;
    s_mapping->apply(moved, mapped);
    const Eigen::Matrix3Xd expected = (rotation * s_anatomy->visualMesh.vertices).colwise() + translation;
    // Rounding only: coordinates of ~0.5 m times a few ulps.
    EXPECT_LT((mapped - expected).colwise().norm().maxCoeff(), 1e-9);
}

/// A smooth bend: each point rotates about the x axis through (0, 0, 0.3) by
/// an angle growing with its height.
Eigen::Matrix3Xd bend(const Eigen::Matrix3Xd& x)
{
    Eigen::Matrix3Xd out(3, x.cols());
    const Eigen::Vector3d pivot(0.0, 0.0, 0.3);
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
        const double angle = 0.5 * x(2, i);  // rad per metre of height
        out.col(i) = pivot + Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()) * (x.col(i) - pivot);
    }
    return out;
}

TEST_F(MeshMappingOnColon, SmoothBendLeavesNoCracks)
{
    Eigen::Matrix3Xd mapped;
    s_mapping->apply(bend(s_anatomy->physicsMesh.vertices), mapped);
    const Eigen::Matrix3Xd truth = bend(s_anatomy->visualMesh.vertices);
    // The bend shears the body by up to 0.5 rad/m x 0.25 m ~ 0.13; a visual
    // vertex sits up to a fold depth (4 mm) off the physics facets, so the
    // mapped surface may differ from the exactly bent one by ~0.13 x 4 mm.
    const double maxDeviation = (mapped - truth).colwise().norm().maxCoeff();
    std::cout << "bend: max deviation from the exact bend " << maxDeviation << " m\n";
    EXPECT_LT(maxDeviation, 1e-3);
    // Cracks would show as edges that stretch: with per-face normals, an edge
    // crossing a physics edge would open by offset x normal jump ~ 4 mm x 0.2
    // rad ~ 0.8 mm. Every visual edge (~2 mm) keeps its length within
    // 20% + 0.2 mm of the exactly bent edge.
    double worstStretch = 0.0;
    for (const auto& t : s_anatomy->visualMesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)];
            const int b = t[static_cast<std::size_t>((k + 1) % 3)];
            const double exact = (truth.col(a) - truth.col(b)).norm();
            const double got = (mapped.col(a) - mapped.col(b)).norm();
            worstStretch = std::max(worstStretch, std::abs(got - exact) - 0.2 * exact);
        }
    }
    EXPECT_LT(worstStretch, 2e-4);
}

TEST_F(MeshMappingOnColon, ApplyReusesItsOutput)
{
    Eigen::Matrix3Xd mapped;
    s_mapping->apply(s_anatomy->physicsMesh.vertices, mapped);
    const double* before = mapped.data();
    s_mapping->apply(bend(s_anatomy->physicsMesh.vertices), mapped);
    EXPECT_EQ(mapped.data(), before) << "a sized output must not be reallocated";
}

TEST_F(MeshMappingOnColon, RemapAfterSplittingATriangle)
{
    MeshMapping mapping = *s_mapping;
    // Topology edit: split one triangle at its centroid (new node appended).
    TriangleMesh edited = s_anatomy->physicsMesh;
    const int split = edited.numTriangles() / 2;
    const auto t = edited.triangles[static_cast<std::size_t>(split)];
    const int centre = edited.numVertices();
    edited.vertices.conservativeResize(3, centre + 1);
    edited.vertices.col(centre) =
        (edited.vertices.col(t[0]) + edited.vertices.col(t[1]) + edited.vertices.col(t[2])) / 3.0;
    edited.triangles[static_cast<std::size_t>(split)] = {t[0], t[1], centre};
    edited.triangles.push_back({t[1], t[2], centre});
    edited.triangles.push_back({t[2], t[0], centre});

    std::vector<int> affected;
    for (int i = 0; i < mapping.numVisualVertices(); ++i) {
        const auto& nodes = mapping.bindings()[static_cast<std::size_t>(i)].node;
        if (std::find_first_of(nodes.begin(), nodes.end(), t.begin(), t.end()) != nodes.end()) {
            affected.push_back(i);
        }
    }
    ASSERT_FALSE(affected.empty());
    mapping.remap(affected, edited);
    int usesNewNode = 0;
    for (int i : affected) {
        const auto& nodes = mapping.bindings()[static_cast<std::size_t>(i)].node;
        usesNewNode += std::find(nodes.begin(), nodes.end(), centre) != nodes.end() ? 1 : 0;
    }
    EXPECT_GT(usesNewNode, 0) << "vertices over the split triangle now bind to the new node";
    Eigen::Matrix3Xd mapped;
    mapping.apply(edited.vertices, mapped);
    // A coplanar split leaves every vertex normal unchanged, so the whole
    // visual mesh still round-trips to rounding (1e-9 m, as above).
    EXPECT_LT((mapped - s_anatomy->visualMesh.vertices).colwise().norm().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace colonosim::geometry
