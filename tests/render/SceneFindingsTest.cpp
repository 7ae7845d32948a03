// What a case puts on the wall for the renderer (cli::findingsOf): lesion
// tissue by histology, each bowel region's residual fluid as a pool over its
// segments, and gravity from the patient's position.

#include "trainer_ui/cli/SceneFindings.h"
#include "simcore/physics/Gravity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>

namespace {

using namespace colonosim;

struct TissueCase {
    const char* name;
    cases::Histology histology;
    render::LesionTissue tissue;
};

void PrintTo(const TissueCase& c, std::ostream* out)
{
    *out << c.name;
}

class TissueOfHistology : public ::testing::TestWithParam<TissueCase> {};

TEST_P(TissueOfHistology, IsDrawnAsItsTissue)
{
    cases::SceneSpec scene;
    cases::SceneLesion lesion;
    lesion.histology = GetParam().histology;
    scene.lesions.push_back(lesion);
    const render::WallFindings findings = cli::findingsOf(scene);
    ASSERT_EQ(findings.lesions.size(), 1U);
    EXPECT_EQ(findings.lesions[0].tissue, GetParam().tissue);
}

INSTANTIATE_TEST_SUITE_P(
    Table, TissueOfHistology,
    ::testing::Values(
        TissueCase{"TubularLowGrade", cases::Histology::TubularLowGrade, render::LesionTissue::Adenoma},
        TissueCase{"Villous", cases::Histology::Villous, render::LesionTissue::Adenoma},
        TissueCase{"Hyperplastic", cases::Histology::Hyperplastic, render::LesionTissue::Serrated},
        TissueCase{"SessileSerrated", cases::Histology::SessileSerrated, render::LesionTissue::Serrated},
        TissueCase{"TraditionalSerrated", cases::Histology::TraditionalSerrated,
                   render::LesionTissue::Serrated},
        TissueCase{"Adenocarcinoma", cases::Histology::Adenocarcinoma, render::LesionTissue::Cancer},
        TissueCase{"Lipoma", cases::Histology::Lipoma, render::LesionTissue::Lipoma}),
    [](const ::testing::TestParamInfo<TissueCase>& info) { return std::string(info.param.name); });

TEST(SceneFindings, EachRegionsFluidIsAPoolOverItsSegmentsAndGravityFollowsThePatient)
{
    cases::SceneSpec scene;
    scene.residualFluid[static_cast<size_t>(cases::BowelRegion::Right)] = 40e-6;
    scene.residualFluid[static_cast<size_t>(cases::BowelRegion::Left)] = 15e-6;
    scene.environment.patientPosition = physics::PatientPosition::Supine;
    const render::WallFindings findings = cli::findingsOf(scene);
    ASSERT_EQ(findings.fluid.size(), 2U) << "the transverse region holds none";
    double total = 0.0;
    for (const render::FluidPool& pool : findings.fluid) {
        ASSERT_FALSE(pool.segments.empty());
        const cases::BowelRegion region = cases::bowelRegion(pool.segments[0]);
        for (const geometry::Segment segment : pool.segments) {
            EXPECT_EQ(cases::bowelRegion(segment), region);
        }
        EXPECT_DOUBLE_EQ(pool.volume, scene.residualFluid[static_cast<size_t>(region)]);
        total += pool.volume;
    }
    EXPECT_DOUBLE_EQ(total, 55e-6);
    const auto& right = findings.fluid[0].segments;
    EXPECT_NE(std::find(right.begin(), right.end(), geometry::Segment::Cecum), right.end());
    EXPECT_NE(std::find(right.begin(), right.end(), geometry::Segment::Ascending), right.end());
    EXPECT_TRUE(findings.down.isApprox(physics::downDirection(physics::PatientPosition::Supine)));
}

}  // namespace
