// Texture charts of the wall: the harmonic along-coordinate, the distortion
// measure on maps with known singular values, and the charts on a straight
// tube and on the default colon.

#include "RenderScenes.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/render/CentrelineChart.h"
#include "simcore/render/ChartDistortion.h"
#include "simcore/render/LaplaceChart.h"
#include "simcore/render/WallSurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace colonosim::render {
namespace {

constexpr double kRadius = 0.02;    // m
constexpr double kLength = 0.3;     // m
constexpr double kSpacing = 0.005;  // m
constexpr int kAround = 24;

TEST(LaplaceChart, HarmonicCoordinateIsLinearInLengthOnAStraightTube)
{
    const geometry::TriangleMesh tube = testing::straightTube(kRadius, kLength, kSpacing, kAround);
    const Eigen::VectorXd u =
        harmonicAlongCoordinate(tube, testing::straightCentreline(kRadius, kLength, kSpacing));
    // The tube is intrinsically flat and the cotangent Laplacian reproduces
    // linear functions on flat meshes: only the solver's rounding is left.
    for (int v = 0; v < tube.numVertices(); ++v) {
        EXPECT_NEAR(u(v), tube.vertices(2, v) / kLength, 1e-9) << "vertex " << v;
    }
}

TEST(LaplaceChart, RefusesAMeshWithoutAnOpenEnd)
{
    geometry::TriangleMesh tetrahedron;
    tetrahedron.vertices.resize(3, 4);
    tetrahedron.vertices << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
    tetrahedron.vertices *= 0.01;
    tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    try {
        (void)laplaceChart(tetrahedron, testing::straightCentreline(kRadius, kLength, kSpacing));
        FAIL() << "a closed mesh was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("no open end"), std::string::npos) << e.what();
    }
}

TEST(ChartDistortion, RefusesAChartOfTheWrongSize)
{
    const geometry::TriangleMesh tube = testing::straightTube(kRadius, kLength, kSpacing, kAround);
    try {
        (void)measureChartDistortion(tube, std::vector<float>(5));
        FAIL() << "a chart of 5 floats was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("chart: has 5 floats"), std::string::npos) << e.what();
    }
}

struct MapCase {
    const char* name;
    Eigen::Matrix2d jacobian;
    double sigma1;
    double sigma2;
    bool flipped;
};

class TriangleStretchTest : public ::testing::TestWithParam<MapCase> {};

TEST_P(TriangleStretchTest, GivesTheMapsSingularValues)
{
    const MapCase& c = GetParam();
    // A triangle in a tilted plane: planar corners rotated into 3D.
    const Eigen::Matrix3d tilt =
        (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
    const std::array<Eigen::Vector2d, 3> planar{Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(3e-3, 0.5e-3),
                                                Eigen::Vector2d(1e-3, 2e-3)};
    std::array<Eigen::Vector3d, 3> surface;
    std::array<Eigen::Vector2d, 3> chart;
    for (size_t i = 0; i < 3; ++i) {
        surface[i] =
            tilt * Eigen::Vector3d(planar[i].x(), planar[i].y(), 0.0) + Eigen::Vector3d(0.1, -0.2, 0.3);
        chart[i] = c.jacobian * planar[i] + Eigen::Vector2d(0.5, -1.0);
    }
    const TriangleStretch t = triangleStretch(surface, chart);
    EXPECT_NEAR(t.sigma1, c.sigma1, 1e-9);
    EXPECT_NEAR(t.sigma2, c.sigma2, 1e-9);
    EXPECT_EQ(t.determinant < 0.0, c.flipped);
}

const double kGolden = (1.0 + std::sqrt(5.0)) / 2.0;  // singular values of the shear [[1 1] [0 1]]

INSTANTIATE_TEST_SUITE_P(
    KnownMaps, TriangleStretchTest,
    ::testing::Values(
        MapCase{"isometry", Eigen::Matrix2d::Identity(), 1.0, 1.0, false},
        MapCase{"rotation", Eigen::Rotation2Dd(1.1).toRotationMatrix(), 1.0, 1.0, false},
        MapCase{"scale", 2.0 * Eigen::Matrix2d::Identity(), 2.0, 2.0, false},
        MapCase{"stretch", Eigen::Vector2d(2.0, 0.5).asDiagonal().toDenseMatrix(), 2.0, 0.5, false},
        MapCase{"shear", (Eigen::Matrix2d() << 1.0, 1.0, 0.0, 1.0).finished(), kGolden, 1.0 / kGolden, false},
        MapCase{"reflection", Eigen::Vector2d(1.0, -1.0).asDiagonal().toDenseMatrix(), 1.0, 1.0, true}),
    [](const ::testing::TestParamInfo<MapCase>& info) { return std::string(info.param.name); });

TEST(ChartDistortion, BothChartsAreIsometricOnAStraightTube)
{
    const geometry::TriangleMesh tube = testing::straightTube(kRadius, kLength, kSpacing, kAround);
    const geometry::Centreline centreline = testing::straightCentreline(kRadius, kLength, kSpacing);
    // The mesh's chords are shorter than the chart's arcs by
    // sin(pi/24) / (pi/24) = 0.9971: stretch within 1% of 1.
    for (const auto& chart : {centrelineChart(tube, centreline, nearestCentrelineSamples(tube, centreline)),
                              laplaceChart(tube, centreline)}) {
        const ChartDistortion d = measureChartDistortion(tube, chart);
        EXPECT_EQ(d.numTears, 0);
        EXPECT_LT(d.stretch.max, 1.01);
        EXPECT_GT(d.areaRatio.mean, 0.99);
        EXPECT_LT(d.areaRatio.max, 1.01);
    }
}

// Measured on the default colon (bench_chart): p99 stretch 1.95 for the
// centreline chart, 1.94 for the Laplace chart; both have a systematic
// stretch of about 1.45 from the haustral folds and the chart's radius being
// the distended centreline radius. The bound leaves 13% above that and fails
// for a chart whose angle is halved (p99 far above it, many tears).
constexpr double kMaxP99Stretch = 2.2;

TEST(ChartDistortion, TheWallChartOfTheDefaultColonHasNoTearsAndBoundedStretch)
{
    // The renderer's chart is the Laplace chart, chosen because its p99
    // stretch is not above the centreline chart's (and 18% below it in tight
    // flexures, bench_chart).
    const geometry::ColonAnatomy colon = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const WallSurface surface = buildWallSurface(colon.visualMesh, colon.centreline, WallFindings{});
    EXPECT_EQ(surface.chart, laplaceChart(colon.visualMesh, colon.centreline));
    const ChartDistortion wall = measureChartDistortion(colon.visualMesh, surface.chart);
    EXPECT_EQ(wall.numTears, 0);
    EXPECT_LT(wall.stretch.p99, kMaxP99Stretch);
    const ChartDistortion centreline = measureChartDistortion(
        colon.visualMesh, centrelineChart(colon.visualMesh, colon.centreline,
                                          nearestCentrelineSamples(colon.visualMesh, colon.centreline)));
    EXPECT_EQ(centreline.numTears, 0);
    EXPECT_LE(wall.stretch.p99, centreline.stretch.p99);
}

TEST(WallSurface, AMarkPlaceIsTheChartOfTheNearestRestVertex)
{
    const geometry::TriangleMesh tube = testing::straightTube(kRadius, kLength, kSpacing, kAround);
    const geometry::Centreline centreline = testing::straightCentreline(kRadius, kLength, kSpacing);
    const WallSurface surface = buildWallSurface(tube, centreline, WallFindings{});
    for (const int v : {0, 7, tube.numVertices() / 2, tube.numVertices() - 1}) {
        const auto k = static_cast<size_t>(v);
        // 0.1 mm off the vertex, well inside its neighbourhood.
        const Eigen::Vector3d p = tube.vertices.col(v) + Eigen::Vector3d(1e-4, 0.0, 0.0);
        const WallPlace place = chartPlaceAt(surface, p);
        EXPECT_EQ(place.arcLength, surface.chart[3 * k]) << "vertex " << v;
        EXPECT_DOUBLE_EQ(place.angle, std::atan2(surface.chart[3 * k + 2], surface.chart[3 * k + 1]));
    }
    try {
        (void)chartPlaceAt(tube.vertices, std::vector<float>(5), Eigen::Vector3d::Zero());
        ADD_FAILURE() << "a chart of the wrong size was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("5 chart values"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace colonosim::render
