// The endoscope view of the default procedural colon (haustral folds,
// findings, preparation), seen from its centreline in the sigmoid.

#include "RenderScenes.h"

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/render/EndoscopeView.h"
#include "simcore/render/OffscreenContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace colonosim;

const geometry::ColonAnatomy& colon()
{
    static const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon({});
    return anatomy;
}

/// On the centreline at arc length s, looking along it.
render::CameraPose centrelinePose(double s)
{
    const geometry::Centreline& c = colon().centreline;
    size_t k = 0;
    while (k + 1 < c.arcLength.size() && c.arcLength[k] < s) {
        ++k;
    }
    render::CameraPose pose;
    pose.position = c.points[k];
    pose.rotation.col(2) = c.tangents[k];
    pose.rotation.col(1) = c.normals[k];
    pose.rotation.col(0) = c.normals[k].cross(c.tangents[k]);
    return pose;
}

render::RgbaImage renderColon(const render::WallFindings& findings, double s,
                              const geometry::ColonAnatomy& anatomy = colon(),
                              const render::RenderParameters& parameters = {}, int width = 480,
                              int height = 360)
{
    render::OffscreenContext context(width, height);
    const render::WallSurface surface =
        render::buildWallSurface(anatomy.visualMesh, anatomy.centreline, findings);
    render::EndoscopeView view(context.gl(), surface, parameters);
    view.render(centrelinePose(s), {}, width, height);
    return context.readBack();
}

/// Fraction of the lit pixels (luminance above 0.15) that are brown-yellow:
/// blue below half of green (the mucosa's pink has B/G about 0.75, the
/// stool's brown about 0.35).
double stoolLike(const render::RgbaImage& image)
{
    int lit = 0;
    int brown = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (colonosim::testing::luminance(image, x, y) > 0.15) {
                ++lit;
                brown += image.at(x, y)[2] < 0.5 * image.at(x, y)[1] ? 1 : 0;
            }
        }
    }
    return lit > 0 ? static_cast<double>(brown) / lit : 0.0;
}

TEST(ColonView, FindingsAndResidualStoolInTheSigmoid)
{
    const double s = 0.22;  // m from the anus: the sigmoid of the default colon
    ASSERT_EQ(colon().centreline.segment[static_cast<size_t>(s / colon().centreline.length() *
                                                             (colon().centreline.numPoints() - 1))],
              geometry::Segment::Sigmoid);
    render::WallFindings findings;
    findings.lesions.push_back(
        {{s + 0.05, 0.5}, 0.012, render::LesionShape::Pedunculated, render::LesionTissue::Adenoma});
    findings.lesions.push_back(
        {{s + 0.04, 2.6}, 0.015, render::LesionShape::Flat, render::LesionTissue::Serrated});
    findings.lesions.push_back(
        {{s + 0.06, 4.2}, 0.02, render::LesionShape::Sessile, render::LesionTissue::Cancer});
    findings.diverticula.push_back({{s + 0.035, 1.6}, 0.006});
    const render::RgbaImage clean = renderColon(findings, s);
    colonosim::testing::saveArtefact(clean, "sigmoid_findings.png");

    findings.stoolFraction[static_cast<size_t>(geometry::Segment::Sigmoid)] = 0.5;
    const render::RgbaImage stool = renderColon(findings, s);
    colonosim::testing::saveArtefact(stool, "sigmoid_stool.png");
    // Half the sigmoid's mucosa under stool: a good part of the lit wall
    // turns brown-yellow, where the clean wall has next to none.
    EXPECT_LT(stoolLike(clean), 0.02);
    EXPECT_GT(stoolLike(stool), 0.10) << stoolLike(stool);
}

/// Mean luminance of the 7 x 7 block centred on (x, y).
double blockLuminance(const render::RgbaImage& image, int x, int y)
{
    double sum = 0.0;
    for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
            sum += colonosim::testing::luminance(image, x + dx, y + dy) / 49.0;
        }
    }
    return sum;
}

/// The far lumen: the centroid of the darkest 3% of the pixels inside the
/// image circle (each the mean of a 7 x 7 block, so a vessel is no lumen).
Eigen::Vector2d lumenCentre(const render::RgbaImage& image)
{
    std::vector<std::pair<double, Eigen::Vector2d>> pixels;
    for (int y = 3; y < image.height - 3; y += 2) {
        for (int x = 3; x < image.width - 3; x += 2) {
            if (std::hypot(x + 0.5 - image.width / 2.0, y + 0.5 - image.height / 2.0) <
                0.9 * image.height / 2.0) {
                pixels.emplace_back(blockLuminance(image, x, y), Eigen::Vector2d(x + 0.5, y + 0.5));
            }
        }
    }
    const auto darkest = pixels.begin() + static_cast<long>(pixels.size() * 3 / 100);
    std::nth_element(pixels.begin(), darkest, pixels.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (auto it = pixels.begin(); it != darkest; ++it) {
        sum += it->second;
    }
    return sum / static_cast<double>(darkest - pixels.begin());
}

/// Luminance (7 x 7 block means) along the ray from `origin` at `angle`
/// (rad) every 2 pixels until the ray leaves 95% of the image circle.
std::vector<double> rayProfile(const render::RgbaImage& image, const Eigen::Vector2d& origin, double angle)
{
    std::vector<double> profile;
    const Eigen::Vector2d centre(image.width / 2.0, image.height / 2.0);
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    for (double t = 0.0;; t += 2.0) {
        const Eigen::Vector2d p = origin + t * direction;
        if ((p - centre).norm() > 0.95 * image.height / 2.0) {
            break;
        }
        profile.push_back(blockLuminance(image, static_cast<int>(p.x()), static_cast<int>(p.y())));
    }
    return profile;
}

/// The deepest valley of a ray's profile beyond its darkest point (the far
/// lumen), as a ratio: max over b of log((min(max before b, max after b) +
/// 0.02) / (p_b + 0.02)), the 0.02 keeping the noise of the dark lumen out.
/// A profile that rises and then falls (a smooth tube: the wall brightens
/// outwards as it nears the lens, then dims at the edge of the light's cone)
/// has none; bright fold crests with darker valleys behind them make one.
double deepestValley(const std::vector<double>& profile)
{
    const auto first = std::min_element(profile.begin(), profile.end());
    double deepest = 0.0;
    for (auto it = first + 1; it + 1 < profile.end(); ++it) {
        const double before = *std::max_element(first, it);
        const double after = *std::max_element(it + 1, profile.end());
        deepest = std::max(deepest, std::log((std::min(before, after) + 0.02) / (*it + 0.02)));
    }
    return deepest;
}

/// Median over 24 rays from the far lumen of each ray's deepest valley.
double medianValley(const render::RgbaImage& image)
{
    const Eigen::Vector2d lumen = lumenCentre(image);
    std::vector<double> valleys;
    for (int k = 0; k < 24; ++k) {
        valleys.push_back(deepestValley(rayProfile(image, lumen, 2.0 * std::numbers::pi * k / 24)));
    }
    std::nth_element(valleys.begin(), valleys.begin() + 12, valleys.end());
    return valleys[12];
}

// Looking along the straight descending colon from three places: the
// haustral folds make bright rings (their crests facing the lens) and dark
// ones (the valleys behind them) on the way from the far lumen to the image's
// edge; the same colon without folds (haustralFoldDepth 0) brightens
// smoothly outwards. Measured medians at eight places along it (a tenth to
// eight tenths of its length): 0.20-0.41 with folds, 0.03-0.07 without; the
// test asks above 0.15 and below 0.1.
TEST(ColonView, HaustralFoldsGiveAlternatingBandsAlongAStraightSegment)
{
    const geometry::Centreline& c = colon().centreline;
    double first = -1.0;
    double last = -1.0;
    for (int k = 0; k < c.numPoints(); ++k) {
        if (c.segment[static_cast<size_t>(k)] == geometry::Segment::Descending) {
            first = first < 0.0 ? c.arcLength[static_cast<size_t>(k)] : first;
            last = c.arcLength[static_cast<size_t>(k)];
        }
    }
    ASSERT_GT(last - first, 0.1) << "the default descending colon is at least 10 cm long";
    geometry::AnatomyParameters smoothParameters;
    smoothParameters.haustralFoldDepth = 0.0;
    const geometry::ColonAnatomy smoothColon = geometry::buildProceduralColon(smoothParameters);
    for (const double fraction : {0.2, 0.4, 0.6}) {
        const double s = first + fraction * (last - first);
        const render::RgbaImage folds = renderColon({}, s);
        const render::RgbaImage smooth = renderColon({}, s, smoothColon);
        if (fraction == 0.4) {
            colonosim::testing::saveArtefact(folds, "descending_folds.png");
            colonosim::testing::saveArtefact(smooth, "descending_no_folds.png");
        }
        EXPECT_GT(medianValley(folds), 0.15) << "at " << s << " m";
        EXPECT_LT(medianValley(smooth), 0.1) << "at " << s << " m";
    }
}

TEST(ColonView, CoarserLevelsFarAwayLeaveThePictureAsItWas)
{
    // Each place drawn at full detail and with the default levels of detail
    // (within a pixel of geometric error) at the trainer's smallest view,
    // where the levels coarsen most.
    constexpr int kW = 320;
    constexpr int kH = 240;
    render::OffscreenContext context(kW, kH);
    const render::WallSurface surface = render::buildWallSurface(colon().visualMesh, colon().centreline, {});
    render::RenderParameters fullParameters;
    fullParameters.levelOfDetailError = 0.0;
    render::EndoscopeView full(context.gl(), surface, fullParameters);
    render::EndoscopeView levels(context.gl(), surface, render::RenderParameters{});
    for (double s : {0.08, 0.3, 0.6, 0.9, 1.2, 1.5}) {
        full.render(centrelinePose(s), {}, kW, kH);
        const render::RgbaImage a = context.readBack();
        levels.render(centrelinePose(s), {}, kW, kH);
        const render::RgbaImage b = context.readBack();
        double sum = 0.0;
        int far = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                const double d =
                    std::abs(colonosim::testing::luminance(a, x, y) - colonosim::testing::luminance(b, x, y));
                sum += d;
                far += d > 0.05 ? 1 : 0;
            }
        }
        // Within a pixel the light that reaches so far hides the difference
        // (at 8 pixels: a mean of 1.4e-4 to 4.2e-4, up to 219 pixels off).
        EXPECT_LT(sum / (kW * kH), 5e-5) << "at " << s << " m";
        EXPECT_LE(far, 20) << "at " << s << " m";
        EXPECT_LT(levels.drawnTriangles(), full.drawnTriangles() * 3 / 4) << "at " << s << " m";
        EXPECT_GT(levels.drawnTriangles(), 0);
        if (s == 0.6) {
            colonosim::testing::saveArtefact(b, "levels_of_detail_sigmoid.png");
        }
    }
}

}  // namespace
