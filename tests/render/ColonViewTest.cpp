// The endoscope view of the default procedural colon (haustral folds,
// findings, preparation), seen from its centreline in the sigmoid.

#include "RenderScenes.h"

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/render/EndoscopeView.h"
#include "simcore/render/OffscreenContext.h"

#include <gtest/gtest.h>

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

render::RgbaImage renderColon(const render::WallFindings& findings, double s)
{
    render::OffscreenContext context(480, 360);
    const render::WallSurface surface =
        render::buildWallSurface(colon().visualMesh, colon().centreline, findings);
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    view.render(centrelinePose(s), {}, 480, 360);
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

}  // namespace
