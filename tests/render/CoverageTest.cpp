// Coverage against the analytic answer on a straight tube, and the scope-shape view.

#include "RenderScenes.h"

#include "simcore/render/CoverageTracker.h"
#include "simcore/render/OffscreenContext.h"
#include "simcore/render/ShapeView.h"
#include "simcore/render/WallVisibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

namespace {

using namespace colonosim;

TEST(Coverage, StraightTubeSeenLengthMatchesTheAnalyticValue)
{
    // Lens on the axis at z = 0 looking along +z into a tube of radius r.
    // A wall point at depth z is
    //   inside the lens's half field alpha when z >= r / tan(alpha),
    //   within the working distance D when z <= sqrt(D^2 - r^2),
    //   seen at incidence <= beta when r / sqrt(r^2 + z^2) >= cos(beta), i.e. z <= r tan(beta),
    // so the seen length is min(sqrt(D^2 - r^2), r tan(beta)) - r / tan(alpha).
    const double r = 0.02;
    const double length = 0.3;
    const double spacing = 0.004;
    render::RenderParameters parameters;
    parameters.coverageResolution = 256;
    render::OffscreenContext context(64, 64);
    const auto tube = colonosim::testing::straightTube(r, length, spacing, 32);
    render::CoverageTracker tracker(
        context.gl(), tube, std::vector<geometry::Segment>(tube.triangles.size(), geometry::Segment::Sigmoid),
        parameters);
    tracker.observe(tube.vertices, colonosim::testing::axialPose(0.0));

    const double alpha = parameters.fieldOfView / 2.0;
    const double expected =
        std::min(std::sqrt(parameters.workingDistance * parameters.workingDistance - r * r),
                 r * std::tan(parameters.maxIncidence)) -
        r / std::tan(alpha);
    const double seen = tracker.fractionSeen() * length;
    // Tolerance: a triangle counts when any part of it is seen, so each end
    // of the seen band may extend by up to one ring spacing.
    EXPECT_NEAR(seen, expected, 2.0 * spacing) << "seen " << seen << " m, analytic " << expected << " m";
    EXPECT_DOUBLE_EQ(tracker.fractionSeen(geometry::Segment::Sigmoid), tracker.fractionSeen());
    EXPECT_EQ(tracker.fractionSeen(geometry::Segment::Cecum), 0.0);

    // Looking from further in adds the band ahead, and keeps what was seen.
    tracker.observe(tube.vertices, colonosim::testing::axialPose(0.1));
    EXPECT_NEAR(tracker.fractionSeen() * length, 2.0 * expected, 4.0 * spacing);
}

TEST(Coverage, RateLimitedUpdatesAndLesionInView)
{
    render::RenderParameters parameters;
    render::OffscreenContext context(64, 64);
    const auto tube = colonosim::testing::straightTube(0.02, 0.3, 0.004, 32);
    render::CoverageTracker tracker(
        context.gl(), tube, std::vector<geometry::Segment>(tube.triangles.size(), geometry::Segment::Sigmoid),
        parameters);
    // Two lesions: 3 cm ahead of the lens, and 20 cm ahead (beyond working distance).
    tracker.setLesionTriangles({render::trianglesNear(tube, Eigen::Vector3d(0.02, 0.0, 0.03), 0.005),
                                render::trianglesNear(tube, Eigen::Vector3d(0.02, 0.0, 0.2), 0.005)});
    const auto pose = colonosim::testing::axialPose(0.0);
    int updates = 0;
    for (int step = 0; step < 1000; ++step) {  // 1 s at 1 kHz
        updates += tracker.update(step * 1e-3, tube.vertices, pose) ? 1 : 0;
    }
    EXPECT_EQ(updates, 10);  // 10 Hz
    ASSERT_EQ(tracker.lesionsInView().size(), 2U);
    EXPECT_TRUE(tracker.lesionsInView()[0]);
    EXPECT_FALSE(tracker.lesionsInView()[1]);
}

// A haustral fold between the lens and a lesion hides it from the renderer,
// though the lesion is inside the lens's circle, within working distance
// and facing the lens: what the loop's own signal (wallPointInView, no
// occlusion test) counts as in view. Without the fold the renderer shows it.
TEST(Coverage, AFoldInFrontHidesALesionThatThePointTestCountsInView)
{
    constexpr double kRadius = 0.02;
    constexpr int kAround = 32;
    render::RenderParameters parameters;
    render::OffscreenContext context(64, 64);
    geometry::TriangleMesh wall = colonosim::testing::straightTube(kRadius, 0.3, 0.004, kAround);
    const Eigen::Vector3d lesion(kRadius, 0.0, 0.03);
    const std::vector<int> lesionTriangles = render::trianglesNear(wall, lesion, 0.005);
    const auto pose = colonosim::testing::axialPose(0.0);
    ASSERT_TRUE(render::wallPointInView(pose, lesion, Eigen::Vector3d(-1.0, 0.0, 0.0), parameters));

    auto shown = [&](const geometry::TriangleMesh& mesh) {
        render::CoverageTracker tracker(
            context.gl(), mesh,
            std::vector<geometry::Segment>(mesh.triangles.size(), geometry::Segment::Sigmoid), parameters);
        tracker.setLesionTriangles({lesionTriangles});
        tracker.observe(mesh.vertices, pose);
        return static_cast<bool>(tracker.lesionsInView()[0]);
    };
    EXPECT_TRUE(shown(wall));

    // The fold: an annulus at z = 2 cm from the wall in to 8 mm of the axis.
    // The ray to the lesion crosses z = 2 cm at 13 mm from the axis.
    geometry::TriangleMesh folded = wall;
    const auto first = static_cast<int>(folded.vertices.cols());
    folded.vertices.conservativeResize(3, first + 2 * kAround);
    for (int j = 0; j < kAround; ++j) {
        const double a = 2.0 * std::numbers::pi * j / kAround;
        folded.vertices.col(first + j) = Eigen::Vector3d(0.008 * std::cos(a), 0.008 * std::sin(a), 0.02);
        folded.vertices.col(first + kAround + j) =
            Eigen::Vector3d(0.0199 * std::cos(a), 0.0199 * std::sin(a), 0.02);
    }
    for (int j = 0; j < kAround; ++j) {
        const int in0 = first + j, in1 = first + (j + 1) % kAround;
        folded.triangles.push_back({in0, in1, in1 + kAround});
        folded.triangles.push_back({in0, in1 + kAround, in0 + kAround});
    }
    EXPECT_FALSE(shown(folded)) << "the fold hides the lesion from the lens";
}

TEST(ShapeView, DrawsColonScopeAndHighlightedLoop)
{
    constexpr int kWidth = 480;
    constexpr int kHeight = 240;
    render::OffscreenContext context(kWidth, kHeight);
    render::ShapeView view(context.gl());
    // An S-shaped colon in the coronal plane and a scope along it.
    geometry::Centreline colon;
    std::vector<Eigen::Vector3d> scope;
    for (int k = 0; k <= 200; ++k) {
        const double s = k * 0.002;
        colon.points.emplace_back(0.05 * std::sin(s * 20.0), 0.0, s);
        colon.arcLength.push_back(s);
        colon.tangents.emplace_back(0.0, 0.0, 1.0);
        colon.normals.emplace_back(1.0, 0.0, 0.0);
        colon.radius.push_back(0.02);
        colon.segment.push_back(k < 100 ? geometry::Segment::Rectum : geometry::Segment::Sigmoid);
        if (k % 10 == 0) {
            scope.push_back(colon.points.back());
        }
    }
    view.render(colon, scope, geometry::Segment::Sigmoid, 0.013, kWidth, kHeight);
    const render::RgbaImage image = context.readBack();
    colonosim::testing::saveArtefact(image, "shape_view.png");
    int green[2] = {0, 0};
    int orange[2] = {0, 0};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const auto* p = image.at(x, y);
            const int panel = x < kWidth / 2 ? 0 : 1;
            green[panel] += p[1] > 180 && p[0] < 120 ? 1 : 0;
            orange[panel] += p[0] > 220 && p[1] > 80 && p[1] < 150 && p[2] < 60 ? 1 : 0;
        }
    }
    for (int panel = 0; panel < 2; ++panel) {
        EXPECT_GT(green[panel], 50) << "panel " << panel;   // the shaft outside the loop
        EXPECT_GT(orange[panel], 50) << "panel " << panel;  // the looped part
    }
    // Without a loop nothing is highlighted.
    view.render(colon, scope, std::nullopt, 0.013, kWidth, kHeight);
    const render::RgbaImage plain = context.readBack();
    int plainOrange = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const auto* p = plain.at(x, y);
            plainOrange += p[0] > 220 && p[1] > 80 && p[1] < 150 && p[2] < 60 ? 1 : 0;
        }
    }
    EXPECT_EQ(plainOrange, 0);
}

}  // namespace
