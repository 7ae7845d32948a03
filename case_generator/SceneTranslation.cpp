#include "case_generator/SceneSpec.h"

#include <algorithm>
#include <cmath>

namespace colonosim::cases {

std::string_view componentName(SceneComponent component)
{
    switch (component) {
    case SceneComponent::Colon: return "colon";
    case SceneComponent::Mesentery: return "mesentery";
    case SceneComponent::Organs: return "organs";
    case SceneComponent::Insufflation: return "insufflation";
    case SceneComponent::Colonoscope: return "colonoscope";
    case SceneComponent::Lesions: return "lesions";
    case SceneComponent::Diverticula: return "diverticula";
    case SceneComponent::Adhesions: return "adhesions";
    case SceneComponent::ResidualFluid: return "residual_fluid";
    case SceneComponent::ColitisMucosa: return "colitis_mucosa";
    case SceneComponent::Snare: return "snare";
    }
    return "unknown";
}

bool SceneSpec::needs(SceneComponent component) const
{
    return std::find(components.begin(), components.end(), component) != components.end();
}

namespace {

/// A value read from a file sits on its declared bound up to the rounding of
/// the unit conversion; such a value is put on the bound, anything further
/// out is left for validate() to refuse.
double onDeclaredRange(double value, const params::ParameterSpec& spec)
{
    const double slack = 1e-12 * std::max(std::abs(spec.minValue), std::abs(spec.maxValue));
    if (value < spec.minValue && value >= spec.minValue - slack) {
        return spec.minValue;
    }
    if (value > spec.maxValue && value <= spec.maxValue + slack) {
        return spec.maxValue;
    }
    return value;
}

ScenePlace scenePlace(const WallPlace& place, const CaseAnatomy& anatomy)
{
    double arc = 0.0;
    for (int i = 0; i < static_cast<int>(place.segment); ++i) {
        arc += anatomy.length[i];
    }
    return {place.segment, arc + place.position, place.clockAngle};
}

}  // namespace

SceneSpec toScene(const Case& c)
{
    SceneSpec scene;
    geometry::AnatomyParameters& a = scene.anatomy;
    const auto fields = geometry::AnatomyParameters::fields();
    for (int i = 0; i < geometry::kNumSegments; ++i) {
        a.*fields[i].member = onDeclaredRange(c.anatomy.length[i], *fields[i].spec);
        const auto& diameter = fields[geometry::kNumSegments + i];
        a.*diameter.member = onDeclaredRange(c.anatomy.diameter[i], *diameter.spec);
    }
    using AP = geometry::AnatomyParameters;
    a.ascendingMobileFraction =
        onDeclaredRange(c.anatomy.ascendingMobileFraction, AP::ascendingMobileFractionSpec);
    a.descendingMobile = c.anatomy.descendingMobile ? 1.0 : 0.0;
    a.transverseMesenteryHeight =
        onDeclaredRange(c.anatomy.transverseMesenteryHeight, AP::transverseMesenteryHeightSpec);
    a.sigmoidMesenteryHeight =
        onDeclaredRange(c.anatomy.sigmoidMesenteryHeight, AP::sigmoidMesenteryHeightSpec);
    a.mobileColonMesenteryHeight =
        onDeclaredRange(c.anatomy.mobileColonMesenteryHeight, AP::mobileColonMesenteryHeightSpec);
    a.validate();

    using TP = physics::TissueParameters;
    physics::TissueParameters& t = scene.tissue;
    t.wallYoungModulus = onDeclaredRange(c.tissue.wallYoungModulus, TP::youngModulusSpec);
    t.wallThickness = onDeclaredRange(c.tissue.wallThickness, TP::thicknessSpec);
    t.mesenteryModulus = onDeclaredRange(c.tissue.mesenteryModulus, TP::mesenteryModulusSpec);
    t.mesenteryThickness = onDeclaredRange(c.tissue.mesenteryThickness, TP::mesenteryThicknessSpec);
    t.adhesionStiffness = onDeclaredRange(c.tissue.adhesionStiffness, TP::adhesionSpec);
    t.surroundingDampingRate = onDeclaredRange(c.tissue.surroundingDampingRate, TP::surroundingDampingSpec);
    t.validate();

    scene.environment.insufflationPressure =
        onDeclaredRange(c.environment.insufflationPressure, physics::EnvironmentParameters::pressureSpec);
    scene.environment.patientPosition = physics::PatientPosition::LeftLateral;
    scene.environment.validate();

    for (const Lesion& l : c.lesions) {
        scene.lesions.push_back(
            {scenePlace(l.place, c.anatomy), l.size, l.stiffness, l.paris, l.histology, l.colour, l.surface});
    }
    for (const Diverticulum& d : c.diverticula) {
        scene.diverticula.push_back({scenePlace(d.place, c.anatomy), d.diameter});
    }
    for (const Adhesion& adhesion : c.adhesions) {
        scene.adhesions.push_back(scenePlace(adhesion.place, c.anatomy));
    }
    bool fluid = false;
    for (int r = 0; r < kNumBowelRegions; ++r) {
        scene.residualStool[r] = c.environment.preparation[r].residualStool;
        scene.residualFluid[r] = c.environment.preparation[r].residualFluid;
        fluid = fluid || scene.residualFluid[r] > 0.0;
    }
    scene.colitis = c.colitis;
    scene.bleedingRisk = c.history.anticoagulant != Anticoagulant::None;

    using C = SceneComponent;
    scene.components = {C::Colon, C::Mesentery, C::Organs, C::Insufflation, C::Colonoscope};
    if (!scene.lesions.empty()) {
        scene.components.push_back(C::Lesions);
    }
    if (!scene.diverticula.empty()) {
        scene.components.push_back(C::Diverticula);
    }
    if (!scene.adhesions.empty()) {
        scene.components.push_back(C::Adhesions);
    }
    if (fluid) {
        scene.components.push_back(C::ResidualFluid);
    }
    if (c.colitis != ColitisExtent::None) {
        scene.components.push_back(C::ColitisMucosa);
    }
    if (c.task == TrainingTask::Polypectomy) {
        scene.components.push_back(C::Snare);
    }
    return scene;
}

}  // namespace colonosim::cases
