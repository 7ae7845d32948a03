// What the trainee sees of the findings and the preparation in a straight
// tube (OSMesa, headless): wet-mucosa highlights, a depressed lesion, a
// diverticulum, a lipoma against an adenoma, and residual fluid.

#include "RenderScenes.h"

#include "simcore/render/EndoscopeView.h"
#include "simcore/render/OffscreenContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace colonosim;
using colonosim::testing::axialPose;
using colonosim::testing::luminance;

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kRadius = 0.02;  // m, a descending colon
constexpr double kLength = 0.30;  // m

render::RgbaImage renderTube(const render::WallFindings& findings, const render::CameraPose& pose,
                             const render::RenderParameters& parameters = {})
{
    render::OffscreenContext context(kWidth, kHeight);
    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const render::WallSurface surface = render::buildWallSurface(tube, centreline, findings);
    render::EndoscopeView view(context.gl(), surface, parameters);
    view.render(pose, {}, kWidth, kHeight);
    return context.readBack();
}

Eigen::Vector2d projected(const render::CameraPose& pose, const Eigen::Vector3d& point)
{
    const render::FisheyeLens lens{render::RenderParameters{}.fieldOfView, kWidth, kHeight};
    const auto pixel = lens.project(pose, point);
    EXPECT_TRUE(pixel.has_value());
    return pixel.value_or(Eigen::Vector2d(kWidth / 2.0, kHeight / 2.0));
}

Eigen::Vector3d wallPoint(const render::WallPlace& place)
{
    return render::wallPoint(colonosim::testing::straightCentreline(kRadius, kLength, 0.001), place);
}

/// Mean of `f(pixel)` over a (2 half + 1)^2 window centred on `centre`.
template <typename F>
double windowMean(const render::RgbaImage& image, const Eigen::Vector2d& centre, int half, F f)
{
    double sum = 0.0;
    int count = 0;
    for (int dy = -half; dy <= half; ++dy) {
        for (int dx = -half; dx <= half; ++dx) {
            const int x = std::clamp(static_cast<int>(centre.x()) + dx, 0, kWidth - 1);
            const int y = std::clamp(static_cast<int>(centre.y()) + dy, 0, kHeight - 1);
            sum += f(image, x, y);
            ++count;
        }
    }
    return sum / count;
}

/// Looking at the wall (+x) from `distance` off it, up along the tube.
render::CameraPose facingWall(double distance)
{
    return colonosim::testing::facingWall(kRadius, distance);
}

/// A highlight pixel: bright in every channel (the mucosa's own pink has
/// green and blue below 65% of red, so lit mucosa alone is never one).
bool isHighlight(const render::RgbaImage& image, int x, int y)
{
    const auto* p = image.at(x, y);
    const int lo = std::min({p[0], p[1], p[2]});
    const int hi = std::max({p[0], p[1], p[2]});
    return lo >= 190 && hi - lo <= 0.2 * hi;
}

int countHighlights(const render::RgbaImage& image)
{
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            count += isHighlight(image, x, y) ? 1 : 0;
        }
    }
    return count;
}

TEST(FindingsView, WetMucosaFacingTheLightHasSpecularHighlightsThatVanishWithoutSpecular)
{
    const render::CameraPose pose = facingWall(0.015);
    const render::RgbaImage wet = renderTube({}, pose);
    render::RenderParameters dry;
    dry.specular = 0.0;
    const render::RgbaImage matte = renderTube({}, pose, dry);
    colonosim::testing::saveArtefact(wet, "specular_wet.png");
    colonosim::testing::saveArtefact(matte, "specular_off.png");
    // The wall straight ahead faces the light (at the lens): near-white,
    // unsaturated spots there, a few hundred pixels of the 45,000 in the
    // circle; none when the specular strength is 0.
    const int highlights = countHighlights(wet);
    EXPECT_GT(highlights, 50);
    EXPECT_LT(highlights, kWidth * kHeight / 4) << "highlights are spots, not the whole wall";
    EXPECT_EQ(countHighlights(matte), 0);
    // They lie on the wall facing the lens: within the middle third of the image.
    int central = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (isHighlight(wet, x, y) && std::abs(x - kWidth / 2) < kHeight / 3 &&
                std::abs(y - kHeight / 2) < kHeight / 3) {
                ++central;
            }
        }
    }
    EXPECT_GT(central, highlights / 2);
}

double redShare(const render::RgbaImage& image, int x, int y)
{
    const auto* p = image.at(x, y);
    return p[0] / (1.0 + p[0] + p[1] + p[2]);
}

double luma(const render::RgbaImage& image, int x, int y)
{
    return luminance(image, x, y);
}

// The same adenoma, 15 mm across, 2.5 cm ahead on the wall, as a 0-IIc
// depression and as a 0-Is dome: the dome rises towards the light and is
// brighter where the lens projects the lesion; the depression is no
// brighter than the wall around it and keeps the lesion's colour there.
TEST(FindingsView, DepressedLesionIsDarkerThanARaisedOneWhereTheLensProjectsIt)
{
    const render::WallPlace place{0.045, -0.7};
    const render::CameraPose pose = axialPose(0.02);
    render::WallFindings depressed;
    depressed.lesions.push_back(
        {place, 0.015, render::LesionShape::Depressed, render::LesionTissue::Adenoma});
    render::WallFindings raised = depressed;
    raised.lesions[0].shape = render::LesionShape::Sessile;
    const render::RgbaImage flatImage = renderTube(depressed, pose);
    const render::RgbaImage domeImage = renderTube(raised, pose);
    const render::RgbaImage none = renderTube({}, pose);
    colonosim::testing::saveArtefact(flatImage, "lesion_depressed.png");
    colonosim::testing::saveArtefact(domeImage, "lesion_raised.png");

    const Eigen::Vector2d centre = projected(pose, wallPoint(place));
    const double dome = windowMean(domeImage, centre, 3, luma);
    const double dip = windowMean(flatImage, centre, 3, luma);
    const double wall = windowMean(none, centre, 3, luma);
    EXPECT_LT(dip, 0.85 * dome) << "depressed " << dip << " raised " << dome;
    EXPECT_LT(dip, 1.05 * wall) << "depressed " << dip << " no lesion " << wall;
    // The adenoma's colour is there (not only relief): redder than the
    // mucosa, whose vessels it hides.
    EXPECT_NE(windowMean(flatImage, centre, 3, redShare), windowMean(none, centre, 3, redShare));
    int changed = 0;
    for (int dy = -6; dy <= 6; ++dy) {
        for (int dx = -6; dx <= 6; ++dx) {
            const int x = static_cast<int>(centre.x()) + dx;
            const int y = static_cast<int>(centre.y()) + dy;
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                d += std::abs(flatImage.at(x, y)[c] - none.at(x, y)[c]);
            }
            changed += d > 30 ? 1 : 0;
        }
    }
    EXPECT_GT(changed, 40) << "the depressed lesion changes the pixels where the lens projects it";
}

// A diverticulum (8 mm) 3 cm ahead: a dark, round opening where the lens
// projects its mouth.
TEST(FindingsView, DiverticulumAheadIsADarkRoundOpeningWhereTheLensProjectsIt)
{
    const render::WallPlace place{0.05, 2.2};
    const render::CameraPose pose = axialPose(0.02);
    render::WallFindings findings;
    findings.diverticula.push_back({place, 0.008});
    const render::RgbaImage with = renderTube(findings, pose);
    const render::RgbaImage without = renderTube({}, pose);
    colonosim::testing::saveArtefact(with, "diverticulum_ahead.png");

    const Eigen::Vector2d centre = projected(pose, wallPoint(place));
    EXPECT_LT(windowMean(with, centre, 2, luma), 0.4 * windowMean(without, centre, 2, luma));
    // The pixels it darkens by half or more: a compact blob around the
    // projected centre, about as wide as tall (an opening seen obliquely is
    // an ellipse; a stripe or scattered pixels are not an opening).
    double sx = 0.0, sy = 0.0;
    int count = 0;
    int xmin = kWidth, xmax = 0, ymin = kHeight, ymax = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (luminance(with, x, y) < 0.5 * luminance(without, x, y) && luminance(without, x, y) > 0.05) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++count;
                xmin = std::min(xmin, x);
                xmax = std::max(xmax, x);
                ymin = std::min(ymin, y);
                ymax = std::max(ymax, y);
            }
        }
    }
    ASSERT_GT(count, 20);
    EXPECT_NEAR(sx / count, centre.x(), 0.05 * kHeight);
    EXPECT_NEAR(sy / count, centre.y(), 0.05 * kHeight);
    const double width = xmax - xmin + 1;
    const double height = ymax - ymin + 1;
    EXPECT_LT(std::max(width, height) / std::min(width, height), 2.5) << width << " x " << height;
    // Filled, not a ring: most of its bounding ellipse is dark.
    EXPECT_GT(count, 0.5 * std::numbers::pi / 4.0 * width * height);
}

/// Yellowness: green above blue, over red (the mucosa's pink about 0.1,
/// yellow 0.4, a white highlight 0).
double yellowness(const render::RgbaImage& image, int x, int y)
{
    const auto* p = image.at(x, y);
    return (p[1] - p[2]) / (1.0 + p[0]);
}

/// Mean square of the fine pattern (luminance minus its 5 x 5 mean) over
/// the (2 half + 1)^2 window at the image centre: shading changes slowly,
/// a pit pattern from pixel to pixel.
double fineTexture(const render::RgbaImage& image, int half)
{
    double sum = 0.0;
    int count = 0;
    for (int y = kHeight / 2 - half; y <= kHeight / 2 + half; ++y) {
        for (int x = kWidth / 2 - half; x <= kWidth / 2 + half; ++x) {
            double mean = 0.0;
            for (int dy = -2; dy <= 2; ++dy) {
                for (int dx = -2; dx <= 2; ++dx) {
                    mean += luminance(image, x + dx, y + dy) / 25.0;
                }
            }
            const double d = luminance(image, x, y) - mean;
            sum += d * d;
            ++count;
        }
    }
    return sum / count;
}

// A lipoma and an adenoma of the same size and shape at the same place: the
// lipoma's region is yellower, and smooth (no pit pattern).
TEST(FindingsView, LipomaIsYellowerThanAnAdenomaAtTheSamePlace)
{
    const render::WallPlace place{0.045, 0.9};
    const render::CameraPose pose = axialPose(0.02);
    render::WallFindings adenoma;
    adenoma.lesions.push_back({place, 0.016, render::LesionShape::Sessile, render::LesionTissue::Adenoma});
    render::WallFindings lipoma = adenoma;
    lipoma.lesions[0].tissue = render::LesionTissue::Lipoma;
    const render::RgbaImage adenomaImage = renderTube(adenoma, pose);
    const render::RgbaImage lipomaImage = renderTube(lipoma, pose);
    const render::RgbaImage none = renderTube({}, pose);
    colonosim::testing::saveArtefact(adenomaImage, "adenoma_ahead.png");
    colonosim::testing::saveArtefact(lipomaImage, "lipoma_ahead.png");

    const auto tube = colonosim::testing::straightTube(kRadius, kLength, 0.002, 64);
    const auto centreline = colonosim::testing::straightCentreline(kRadius, kLength, 0.001);
    const Eigen::Vector2d top =
        projected(pose, render::buildWallSurface(tube, centreline, lipoma).lesionTops[0]);
    const double yellowLipoma = windowMean(lipomaImage, top, 3, yellowness);
    const double yellowAdenoma = windowMean(adenomaImage, top, 3, yellowness);
    const double yellowMucosa = windowMean(none, top, 3, yellowness);
    EXPECT_GT(yellowLipoma, yellowAdenoma + 0.1) << yellowLipoma << " vs " << yellowAdenoma;
    EXPECT_GT(yellowLipoma, yellowMucosa + 0.1) << yellowLipoma << " vs mucosa " << yellowMucosa;
    // Yellow, not white: blue well below green.
    const double blueOverGreen =
        windowMean(lipomaImage, top, 3, [](const render::RgbaImage& image, int x, int y) {
            return image.at(x, y)[2] / (1.0 + image.at(x, y)[1]);
        });
    EXPECT_LT(blueOverGreen, 0.75);

    // Close up (3 cm from the wall, a 25 mm mound straight ahead): the
    // lipoma's surface is the smooth mucosa's; the adenoma's own surface has
    // a pit pattern, fine texture from pixel to pixel (the lipoma has 0.61
    // of the adenoma's; below 0.75 is asked).
    const render::WallPlace ahead{0.15, 0.0};
    const render::CameraPose close = facingWall(0.03);
    render::WallFindings closeLipoma;
    closeLipoma.lesions.push_back({ahead, 0.025, render::LesionShape::Sessile, render::LesionTissue::Lipoma});
    render::WallFindings closeAdenoma = closeLipoma;
    closeAdenoma.lesions[0].tissue = render::LesionTissue::Adenoma;
    const render::RgbaImage lipomaClose = renderTube(closeLipoma, close);
    const render::RgbaImage adenomaClose = renderTube(closeAdenoma, close);
    const render::RgbaImage wallClose = renderTube({}, close);
    colonosim::testing::saveArtefact(lipomaClose, "lipoma_close.png");
    colonosim::testing::saveArtefact(adenomaClose, "adenoma_close.png");
    const double lipomaTexture = fineTexture(lipomaClose, 12);
    const double adenomaTexture = fineTexture(adenomaClose, 12);
    EXPECT_LT(lipomaTexture, 0.75 * adenomaTexture) << lipomaTexture << " vs adenoma " << adenomaTexture;
    EXPECT_GT(windowMean(lipomaClose, {kWidth / 2.0, kHeight / 2.0}, 20, yellowness),
              windowMean(wallClose, {kWidth / 2.0, kHeight / 2.0}, 20, yellowness) + 0.1);
}

/// Fraction of the lit pixels (luminance above 0.04) in rows [y0, y1) that are
/// yellow-brown liquid: green at least 1.6 times blue and red above green.
double fluidLike(const render::RgbaImage& image, int y0, int y1)
{
    int lit = 0;
    int fluid = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const auto* p = image.at(x, y);
            if (luminance(image, x, y) > 0.04) {
                ++lit;
                fluid += p[1] >= 1.6 * p[2] && p[0] > p[1] ? 1 : 0;
            }
        }
    }
    return lit > 0 ? static_cast<double>(fluid) / lit : 0.0;
}

// 35 mL over the 30 cm tube pool on the gravity side, 6 mm deep: the lower
// part of the image (where the lens projects the tube's bottom) turns
// yellow-brown; the upper part and the same view without fluid do not.
TEST(FindingsView, ResidualFluidPoolsOnTheGravitySideAsAYellowBrownLiquid)
{
    const render::CameraPose pose = axialPose(0.02);
    render::WallFindings wet;
    wet.down = -Eigen::Vector3d::UnitY();
    const double area = render::circularSegmentArea(kRadius, 0.006);
    wet.fluid.push_back({{geometry::Segment::Descending}, area * kLength});
    const render::RgbaImage pool = renderTube(wet, pose);
    render::WallFindings dry;
    dry.down = wet.down;
    const render::RgbaImage clean = renderTube(dry, pose);
    colonosim::testing::saveArtefact(pool, "fluid_pool.png");
    colonosim::testing::saveArtefact(clean, "fluid_none.png");

    // Which half of the image is down: where the lens puts the tube's bottom.
    const Eigen::Vector2d bottom = projected(pose, Eigen::Vector3d(0.0, -kRadius, 0.06));
    const bool downIsLow = bottom.y() > kHeight / 2.0;
    const int gravityFrom = downIsLow ? kHeight / 2 : 0;
    const int otherFrom = downIsLow ? 0 : kHeight / 2;
    const double gravitySide = fluidLike(pool, gravityFrom, gravityFrom + kHeight / 2);
    const double otherSide = fluidLike(pool, otherFrom, otherFrom + kHeight / 2);
    EXPECT_GT(gravitySide, 0.15) << gravitySide;
    EXPECT_LT(otherSide, 0.02) << otherSide;
    EXPECT_LT(fluidLike(clean, 0, kHeight), 0.02);
    // The liquid covers the wall's bottom line.
    EXPECT_GT(windowMean(pool, bottom, 2, yellowness), windowMean(clean, bottom, 2, yellowness) + 0.1);
    // The surface is level: the scene is mirror-symmetric about the vertical
    // plane through the axis, so the pool covers as much of the image left of
    // it as right of it (within 15%; the texture under it is not symmetric).
    int left = 0;
    int right = 0;
    for (int y = gravityFrom; y < gravityFrom + kHeight / 2; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const auto* p = pool.at(x, y);
            if (luminance(pool, x, y) > 0.04 && p[1] >= 1.6 * p[2] && p[0] > p[1]) {
                (x < kWidth / 2 ? left : right) += 1;
            }
        }
    }
    EXPECT_NEAR(left, right, 0.15 * std::max(left, right)) << left << " left, " << right << " right";

    // Looking 45 degrees down into the pool: the level surface mirrors the
    // light where it faces the lens, straight below it, as a small spot
    // of highlight pixels centred where the lens projects that point.
    render::CameraPose down;
    down.position = Eigen::Vector3d(0.0, 0.0, 0.05);
    down.rotation.col(2) = Eigen::Vector3d(0.0, -1.0, 1.0).normalized();
    down.rotation.col(1) = Eigen::Vector3d(0.0, 1.0, 1.0).normalized();
    down.rotation.col(0) = down.rotation.col(1).cross(down.rotation.col(2));
    const render::RgbaImage into = renderTube(wet, down);
    colonosim::testing::saveArtefact(into, "fluid_pool_from_above.png");
    const Eigen::Vector2d below = projected(down, Eigen::Vector3d(0.0, -kRadius + 0.006, 0.05));
    double sx = 0.0, sy = 0.0;
    int count = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (isHighlight(into, x, y)) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++count;
            }
        }
    }
    ASSERT_GT(count, 5);
    EXPECT_NEAR(sx / count, below.x(), 0.06 * kHeight);
    EXPECT_NEAR(sy / count, below.y(), 0.06 * kHeight);

    // The lens dipped 3 mm into the pool: the submerged half of the view is
    // a yellow-brown murk, lit, not black.
    render::CameraPose dipped = axialPose(0.02);
    dipped.position.y() = -kRadius + 0.003;
    const render::RgbaImage murk = renderTube(wet, dipped);
    colonosim::testing::saveArtefact(murk, "fluid_lens_in_pool.png");
    EXPECT_GT(fluidLike(murk, gravityFrom, gravityFrom + kHeight / 2), 0.5);
    double lit = 0.0;
    for (int y = gravityFrom; y < gravityFrom + kHeight / 2; ++y) {
        lit += luminance(murk, kWidth / 2, y) / (kHeight / 2);
    }
    EXPECT_GT(lit, 0.05);
}

}  // namespace
