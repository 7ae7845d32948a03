// Case to scene: simcore's declared parameters get the case's values and
// accept them, places become arc lengths, and the scene lists the components
// it needs (a snare only for a polypectomy).

#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"

#include <gtest/gtest.h>

namespace colonosim::cases {

TEST(SceneTranslation, ValuesArriveInTheSimulatorsParameters)
{
    const Case c = CaseGenerator().generate(2024);
    const SceneSpec scene = toScene(c);
    EXPECT_DOUBLE_EQ(scene.anatomy.sigmoidLength, c.anatomy.length[static_cast<int>(Segment::Sigmoid)]);
    EXPECT_DOUBLE_EQ(scene.anatomy.cecumDiameter, c.anatomy.diameter[static_cast<int>(Segment::Cecum)]);
    EXPECT_DOUBLE_EQ(scene.anatomy.transverseMesenteryHeight, c.anatomy.transverseMesenteryHeight);
    EXPECT_EQ(scene.anatomy.isDescendingMobile(), c.anatomy.descendingMobile);
    EXPECT_DOUBLE_EQ(scene.tissue.wallYoungModulus, c.tissue.wallYoungModulus);
    EXPECT_DOUBLE_EQ(scene.tissue.mesenteryThickness, c.tissue.mesenteryThickness);
    EXPECT_DOUBLE_EQ(scene.environment.insufflationPressure, c.environment.insufflationPressure);
    EXPECT_NEAR(
        scene.anatomy.totalLength(),
        [&] {
            double total = 0.0;
            for (const double l : c.anatomy.length) {
                total += l;
            }
            return total;
        }(),
        1e-12);
}

TEST(SceneTranslation, EveryGeneratedCaseIsWithinTheDeclaredRanges)
{
    const CaseGenerator generator;
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
        const Case c = generator.generate(seed);
        SceneSpec scene;
        ASSERT_NO_THROW(scene = toScene(c)) << seed;
        for (std::size_t i = 0; i < c.lesions.size(); ++i) {
            const ScenePlace& p = scene.lesions[i].place;
            EXPECT_GE(p.arcLength, 0.0);
            EXPECT_LE(p.arcLength, scene.anatomy.totalLength() + 1e-12);
            // The arc length lands inside the lesion's own segment.
            double start = 0.0;
            for (int s = 0; s < static_cast<int>(p.segment); ++s) {
                start += scene.anatomy.length(static_cast<Segment>(s));
            }
            EXPECT_GE(p.arcLength, start - 1e-12);
            EXPECT_LE(p.arcLength, start + scene.anatomy.length(p.segment) + 1e-12);
        }
    }
}

TEST(SceneTranslation, ComponentsFollowTheCase)
{
    const CaseGenerator generator;
    Constraints polyp;
    polyp.require = RequireExpression::parse("polypectomy");
    const SceneSpec withSnare = toScene(generator.generate(3, polyp));
    EXPECT_TRUE(withSnare.needs(SceneComponent::Snare));
    EXPECT_TRUE(withSnare.needs(SceneComponent::Lesions));

    Constraints plain;
    plain.require = RequireExpression::parse("lesions=0 and not adhesions and diverticula=0");
    const SceneSpec intubation = toScene(generator.generate(3, plain));
    EXPECT_FALSE(intubation.needs(SceneComponent::Snare));
    EXPECT_FALSE(intubation.needs(SceneComponent::Lesions));
    EXPECT_FALSE(intubation.needs(SceneComponent::Adhesions));
    EXPECT_FALSE(intubation.needs(SceneComponent::Diverticula));
    EXPECT_TRUE(intubation.needs(SceneComponent::Colon));
    EXPECT_TRUE(intubation.needs(SceneComponent::Colonoscope));

    Constraints adhesions;
    adhesions.require = RequireExpression::parse("adhesions");
    const Case withAdhesions = generator.generate(4, adhesions);
    const SceneSpec adhered = toScene(withAdhesions);
    EXPECT_TRUE(adhered.needs(SceneComponent::Adhesions));
    EXPECT_EQ(adhered.adhesions.size(), withAdhesions.adhesions.size());
    EXPECT_DOUBLE_EQ(adhered.tissue.adhesionStiffness, withAdhesions.tissue.adhesionStiffness);
}

// The procedure settings a scene sets: its wall and environment, and its
// lesions' and adhesions' places on the wall, which the loop binds to nodes.
TEST(SceneTranslation, TheSceneSetsTheProcedureLoopsLesionsAndAdhesions)
{
    Constraints both;
    both.require = RequireExpression::parse("adhesions and lesions>=1");
    const SceneSpec scene = toScene(CaseGenerator().generate(4, both));
    ASSERT_FALSE(scene.adhesions.empty());
    ASSERT_FALSE(scene.lesions.empty());
    const procedure::ProcedureSettings settings = procedureSettings(scene);
    EXPECT_DOUBLE_EQ(settings.tissue.adhesionStiffness, scene.tissue.adhesionStiffness);
    EXPECT_DOUBLE_EQ(settings.environment.insufflationPressure, scene.environment.insufflationPressure);
    ASSERT_EQ(settings.adhesions.size(), scene.adhesions.size());
    for (size_t k = 0; k < scene.adhesions.size(); ++k) {
        EXPECT_DOUBLE_EQ(settings.adhesions[k].arcLength, scene.adhesions[k].arcLength);
        EXPECT_DOUBLE_EQ(settings.adhesions[k].angle, scene.adhesions[k].angle);
    }
    ASSERT_EQ(settings.lesions.size(), scene.lesions.size());
    for (size_t k = 0; k < scene.lesions.size(); ++k) {
        EXPECT_DOUBLE_EQ(settings.lesions[k].arcLength, scene.lesions[k].place.arcLength);
    }
}

TEST(SceneTranslation, AValueOutsideTheSimulatorsRangeIsRefused)
{
    Case c = CaseGenerator().generate(1);
    c.tissue.wallYoungModulus = 1e9;
    EXPECT_THROW((void)toScene(c), params::ParameterError);
}

}  // namespace colonosim::cases
