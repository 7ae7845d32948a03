// Image properties of the endoscope view, rendered headless (OSMesa).

#include "RenderScenes.h"

#include "simcore/render/EndoscopeView.h"
#include "simcore/render/OffscreenContext.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

namespace {

using namespace colonosim;
using colonosim::testing::axialPose;
using colonosim::testing::luminance;

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kRadius = 0.02;  // m, a descending colon
constexpr double kLength = 0.30;  // m

struct Frame {
    render::RgbaImage image;
    double redOut = 0.0;
};

Frame renderTube(const render::WallFindings& findings, const render::CameraPose& pose, double soiling = 0.0,
                 const std::vector<render::BleedingMark>& marks = {},
                 double wallDistance = std::numeric_limits<double>::infinity())
{
    render::OffscreenContext context(kWidth, kHeight);
    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const render::WallSurface surface = render::buildWallSurface(tube, centreline, findings);
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    view.setBleedingMarks(marks);
    view.render(pose, {soiling, 0.0, wallDistance}, kWidth, kHeight);
    return {context.readBack(), view.redOut()};
}

/// Mean luminance of the pixels whose distance from the image centre, as a
/// fraction of the image-circle radius (half the height), is in [from, to).
double ringMean(const render::RgbaImage& image, double from, double to)
{
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double r =
                std::hypot(x + 0.5 - image.width / 2.0, y + 0.5 - image.height / 2.0) / (image.height / 2.0);
            if (r >= from && r < to) {
                sum += luminance(image, x, y);
                ++count;
            }
        }
    }
    return count > 0 ? sum / count : 0.0;
}

/// Sums of red, green and blue over the central half of the image (each axis).
std::array<double, 3> centreSums(const render::RgbaImage& image)
{
    std::array<double, 3> sums{};
    for (int y = kHeight / 4; y < 3 * kHeight / 4; ++y) {
        for (int x = kWidth / 4; x < 3 * kWidth / 4; ++x) {
            for (int c = 0; c < 3; ++c) {
                sums[static_cast<size_t>(c)] += image.at(x, y)[c];
            }
        }
    }
    return sums;
}

TEST(EndoscopeView, LumenIsDarkAtTheCentreOfAStraightSegment)
{
    const Frame frame = renderTube({}, axialPose(0.02));
    colonosim::testing::saveArtefact(frame.image, "straight_lumen.png");
    const double centre = ringMean(frame.image, 0.0, 0.12);
    const double wall = ringMean(frame.image, 0.55, 0.9);
    // The far lumen gets light only from beyond ~10 cm (inverse square):
    // it must be much darker than the near wall, which must be clearly lit.
    EXPECT_GT(wall, 0.25);
    EXPECT_LT(centre, 0.25 * wall) << "centre " << centre << " wall " << wall;
    EXPECT_DOUBLE_EQ(frame.redOut, 0.0);
}

TEST(EndoscopeView, RedOutFrameIsDominatedByRed)
{
    // The lens 1 mm from the wall, looking straight at it.
    const Frame frame = renderTube({}, colonosim::testing::facingWall(kRadius, 0.001));
    colonosim::testing::saveArtefact(frame.image, "red_out.png");
    EXPECT_DOUBLE_EQ(frame.redOut, 1.0);
    const auto [r, g, b] = centreSums(frame.image);
    EXPECT_GT(r, 4.0 * g);
    EXPECT_GT(r, 4.0 * b);
}

// Pushed hard, the tip's lens can end up just through the wall's surface,
// facing out of the lumen: no wall lies ahead, and the picture would be
// black. The simulation knows the lens is at the wall (its lens-wall
// distance is 0), and a real scope there shows red-out: so does the view.
TEST(EndoscopeView, ALensPressedThroughTheWallIsRedOutNotBlack)
{
    // 1 mm beyond the wall, facing out of the lumen.
    const render::CameraPose pose = colonosim::testing::facingWall(kRadius, -0.001);
    const Frame blind = renderTube({}, pose);
    EXPECT_DOUBLE_EQ(blind.redOut, 0.0) << "the renderer alone sees no wall ahead";
    EXPECT_LT(ringMean(blind.image, 0.0, 0.9), 0.02) << "and draws black";
    const Frame pressed = renderTube({}, pose, 0.0, {}, 0.0);
    colonosim::testing::saveArtefact(pressed.image, "red_out_through_wall.png");
    EXPECT_DOUBLE_EQ(pressed.redOut, 1.0);
    const auto [r, g, b] = centreSums(pressed.image);
    EXPECT_GT(r, 4.0 * g);
    EXPECT_GT(r, 4.0 * b);
    EXPECT_GT(r / (kWidth * kHeight / 4.0), 40.0) << "red, not black";
    // A lens 2 cm from the wall by the simulation's measure leaves the view as it was.
    EXPECT_DOUBLE_EQ(renderTube({}, pose, 0.0, {}, 0.02).redOut, 0.0);
}

TEST(EndoscopeView, LesionAheadAppearsWhereTheLensProjectsIt)
{
    render::WallFindings findings;
    render::Lesion lesion;
    lesion.place = {0.06, 0.8};
    lesion.diameter = 0.012;
    lesion.shape = render::LesionShape::Sessile;
    findings.lesions.push_back(lesion);
    const render::CameraPose pose = axialPose(0.02);
    const Frame with = renderTube(findings, pose);
    const Frame without = renderTube({}, pose);
    colonosim::testing::saveArtefact(with.image, "lesion_ahead.png");

    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const auto surface = render::buildWallSurface(tube, centreline, findings);
    const render::FisheyeLens lens{render::RenderParameters{}.fieldOfView, kWidth, kHeight};
    const auto expected = lens.project(pose, surface.lesionTops[0]);
    ASSERT_TRUE(expected.has_value());

    // Centroid of the pixels the lesion changed.
    double sx = 0.0, sy = 0.0;
    int count = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            double d = 0.0;
            for (int c = 0; c < 3; ++c) {
                d += std::abs(static_cast<int>(with.image.at(x, y)[c]) -
                              static_cast<int>(without.image.at(x, y)[c]));
            }
            if (d > 60.0) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++count;
            }
        }
    }
    ASSERT_GT(count, 30) << "the lesion changed too few pixels";
    // Tolerance: the lesion is a dome ~12 mm across seen obliquely; its
    // changed pixels' centroid lies within 12% of the image height of its top.
    EXPECT_NEAR(sx / count, expected->x(), 0.12 * kHeight);
    EXPECT_NEAR(sy / count, expected->y(), 0.12 * kHeight);
    // And on the correct side of the image centre.
    EXPECT_EQ(sx / count > kWidth / 2.0, expected->x() > kWidth / 2.0);
    EXPECT_EQ(sy / count > kHeight / 2.0, expected->y() > kHeight / 2.0);
}

// A contact bleeding mark 3 cm ahead of the lens: the pixels around where the
// lens projects its centre are darker and redder than in the same frame
// without it, and the frame elsewhere is unchanged.
TEST(EndoscopeView, BleedingMarkAheadIsADarkRedSpotWhereTheLensProjectsIt)
{
    const render::WallPlace place{0.05, -0.6};
    const render::CameraPose pose = axialPose(0.02);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const Frame with = renderTube({}, pose, 0.0, {{render::wallPoint(centreline, place), 0.004, 1.0}});
    const Frame without = renderTube({}, pose);
    colonosim::testing::saveArtefact(with.image, "bleeding_mark_ahead.png");

    const render::FisheyeLens lens{render::RenderParameters{}.fieldOfView, kWidth, kHeight};
    const auto centre = lens.project(pose, render::wallPoint(centreline, place));
    ASSERT_TRUE(centre.has_value());
    // A 5 x 5 pixel window at the projected centre (the 8 mm spot seen
    // obliquely from 3-4 cm spans more than that).
    double lumaWith = 0.0, lumaWithout = 0.0, redWith = 0.0, redWithout = 0.0;
    const auto redness = [](const render::RgbaImage& image, int x, int y) {
        const auto* p = image.at(x, y);
        return p[0] / (1.0 + p[0] + p[1] + p[2]);
    };
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const int x = static_cast<int>(centre->x()) + dx;
            const int y = static_cast<int>(centre->y()) + dy;
            lumaWith += luminance(with.image, x, y);
            lumaWithout += luminance(without.image, x, y);
            redWith += redness(with.image, x, y);
            redWithout += redness(without.image, x, y);
        }
    }
    EXPECT_LT(lumaWith, 0.7 * lumaWithout) << "darker";
    EXPECT_GT(redWith, redWithout + 0.05 * 25) << "redder (red share of the colour)";
    // Far from the mark (the opposite wall) nothing changes.
    const int ox = kWidth - static_cast<int>(centre->x());
    const int oy = kHeight - static_cast<int>(centre->y());
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(with.image.at(ox, oy)[c], without.image.at(ox, oy)[c]);
    }
}

// One view whose mark darkens (hit again) and then widens draws each frame as
// a view given those marks afresh: the darkening changes only the mark's
// uniforms, the widening also the vertices it reaches.
TEST(EndoscopeView, AMarkThatDarkensOrWidensIsDrawnAsIfSetAfresh)
{
    const render::CameraPose pose = axialPose(0.02);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const Eigen::Vector3d at = render::wallPoint(centreline, render::WallPlace{0.05, -0.6});
    const std::vector<std::vector<render::BleedingMark>> steps = {
        {{at, 0.003, 0.4}}, {{at, 0.003, 0.9}}, {{at, 0.012, 0.9}}};
    std::vector<render::RgbaImage> stepped;
    {
        render::OffscreenContext context(kWidth, kHeight);
        const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
        const render::WallSurface surface = render::buildWallSurface(tube, centreline, {});
        render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
        for (const auto& marks : steps) {
            view.setBleedingMarks(marks);
            view.render(pose, {0.0, 0.0, std::numeric_limits<double>::infinity()}, kWidth, kHeight);
            stepped.push_back(context.readBack());
        }
    }
    for (size_t k = 0; k < steps.size(); ++k) {
        EXPECT_EQ(stepped[k].pixels, renderTube({}, pose, 0.0, steps[k]).image.pixels) << "step " << k;
    }
    EXPECT_NE(stepped[0].pixels, stepped[1].pixels) << "the darker mark shows";
    EXPECT_NE(stepped[1].pixels, stepped[2].pixels) << "the wider mark shows";
}

TEST(EndoscopeView, NearWallDoesNotGlare)
{
    // The lens 5 mm from the wall, looking at it: without the automatic light
    // control the inverse-square light would saturate most of the view.
    render::CameraPose pose;
    pose.position = Eigen::Vector3d(kRadius - 0.005, 0.0, 0.15);
    pose.rotation.col(2) = Eigen::Vector3d::UnitX();
    pose.rotation.col(1) = Eigen::Vector3d::UnitZ();
    pose.rotation.col(0) = pose.rotation.col(1).cross(pose.rotation.col(2));
    const Frame frame = renderTube({}, pose);
    colonosim::testing::saveArtefact(frame.image, "near_wall.png");
    EXPECT_DOUBLE_EQ(frame.redOut, 0.0);
    int saturated = 0;
    int inCircle = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (std::hypot(x + 0.5 - kWidth / 2.0, y + 0.5 - kHeight / 2.0) < 0.9 * kHeight / 2.0) {
                ++inCircle;
                saturated += frame.image.at(x, y)[0] >= 250 ? 1 : 0;
            }
        }
    }
    EXPECT_LT(saturated, inCircle / 20) << saturated << " of " << inCircle << " pixels saturated";
    // And the wall is still well lit where it faces the lens.
    EXPECT_GT(luminance(frame.image, kWidth / 2, kHeight / 2), 0.2);
}

double gradientEnergy(const render::RgbaImage& image)
{
    double sum = 0.0;
    for (int y = 1; y < image.height; ++y) {
        for (int x = 1; x < image.width; ++x) {
            const double r = std::hypot(x - image.width / 2.0, y - image.height / 2.0) / (image.height / 2.0);
            if (r < 0.9) {
                const double gx = luminance(image, x, y) - luminance(image, x - 1, y);
                const double gy = luminance(image, x, y) - luminance(image, x, y - 1);
                sum += gx * gx + gy * gy;
            }
        }
    }
    return sum;
}

TEST(EndoscopeView, LensWashedFrameIsClearerThanSoiledOne)
{
    const render::CameraPose pose = axialPose(0.02);
    const Frame soiled = renderTube({}, pose, 1.0);
    const Frame washed = renderTube({}, pose, 0.0);
    colonosim::testing::saveArtefact(soiled.image, "lens_soiled.png");
    colonosim::testing::saveArtefact(washed.image, "lens_washed.png");
    // Soiling blurs: the washed frame keeps clearly more fine detail.
    EXPECT_GT(gradientEnergy(washed.image), 1.5 * gradientEnergy(soiled.image));
}

/// A view of the tube that draws `lenses` one after another, each image
/// read back; size k of `sizes` for lens k.
std::vector<render::RgbaImage> renderLenses(const render::CameraPose& pose,
                                            const std::vector<render::LensState>& lenses,
                                            const std::vector<std::pair<int, int>>& sizes)
{
    render::OffscreenContext context(kWidth, kHeight);
    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const render::WallSurface surface = render::buildWallSurface(tube, centreline, {});
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    std::vector<render::RgbaImage> images;
    for (size_t k = 0; k < lenses.size(); ++k) {
        view.render(pose, lenses[k], sizes[k].first, sizes[k].second);
        render::RgbaImage image = context.readBack();
        // The context's buffer stays kWidth x kHeight: keep the drawn corner.
        render::RgbaImage drawn;
        drawn.width = sizes[k].first;
        drawn.height = sizes[k].second;
        for (int y = kHeight - drawn.height; y < kHeight; ++y) {
            const auto* row = image.at(0, y);
            drawn.pixels.insert(drawn.pixels.end(), row, row + 4 * drawn.width);
        }
        images.push_back(std::move(drawn));
    }
    return images;
}

TEST(EndoscopeView, ASoiledLensIsDrawnAsIfSetAfreshWhateverCameBefore)
{
    // The droplet mask and the reduced scene are kept between frames: every
    // change of the soiling, its seed or the size must show at once.
    const render::CameraPose pose = axialPose(0.02);
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const std::vector<render::LensState> lenses = {{0.3, 0.0, kInf}, {0.8, 0.0, kInf}, {0.8, 5.0, kInf},
                                                   {0.0, 5.0, kInf}, {0.3, 0.0, kInf}, {0.3, 0.0, kInf}};
    const std::vector<std::pair<int, int>> sizes = {{kWidth, kHeight}, {kWidth, kHeight}, {kWidth, kHeight},
                                                    {kWidth, kHeight}, {kWidth, kHeight}, {160, 120}};
    const std::vector<render::RgbaImage> stepped = renderLenses(pose, lenses, sizes);
    for (size_t k = 0; k < lenses.size(); ++k) {
        const render::RgbaImage fresh = renderLenses(pose, {lenses[k]}, {sizes[k]}).front();
        EXPECT_EQ(stepped[k].pixels, fresh.pixels) << "step " << k;
    }
    EXPECT_NE(stepped[0].pixels, stepped[1].pixels) << "more soiling shows";
    EXPECT_NE(stepped[1].pixels, stepped[2].pixels) << "a new droplet pattern shows";
    EXPECT_NE(stepped[2].pixels, stepped[3].pixels) << "the wash shows";
}

TEST(EndoscopeView, TheSoilingBlursTheSameShareOfTheImageAtAnyScale)
{
    // The blur belongs to the lens, not to the pixels: the view drawn at half
    // the size (the trainer's smallest scale) and the full-size view reduced
    // to it differ under soiling no more than they do clean. (A blur of so
    // many pixels, twice as wide on the half-size view, made the soiled pair
    // differ by 0.0039 against 0.0025 clean.)
    const render::CameraPose pose = axialPose(0.02);
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const auto difference = [&](double soiling) {
        const render::LensState lens{soiling, 0.0, kInf};
        const render::RgbaImage full = renderLenses(pose, {lens}, {{kWidth, kHeight}}).front();
        const render::RgbaImage half = renderLenses(pose, {lens}, {{kWidth / 2, kHeight / 2}}).front();
        double sum = 0.0;
        for (int y = 0; y < kHeight / 2; ++y) {
            for (int x = 0; x < kWidth / 2; ++x) {
                const double reduced =
                    (luminance(full, 2 * x, 2 * y) + luminance(full, 2 * x + 1, 2 * y) +
                     luminance(full, 2 * x, 2 * y + 1) + luminance(full, 2 * x + 1, 2 * y + 1)) /
                    4.0;
                sum += std::abs(reduced - luminance(half, x, y));
            }
        }
        return sum / (kWidth / 2 * kHeight / 2);
    };
    const double clean = difference(0.0);
    const double soiled = difference(0.8);
    EXPECT_LT(soiled, clean + 5e-4) << "clean " << clean;
}

}  // namespace
