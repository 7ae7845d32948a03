#pragma once
/// \file
/// What the simulator needs to build a case's scene: the anatomy and tissue
/// parameters of simcore, the environment, the places of lesions,
/// diverticula and adhesions, and which components the scene must contain
/// (no snare unless the task is a polypectomy). Values are SI.

#include "case_generator/Case.h"
#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/physics/TissueParameters.h"

#include <array>
#include <string_view>
#include <vector>

namespace colonosim::cases {

enum class SceneComponent : std::uint8_t {
    Colon,          ///< wall, always
    Mesentery,      ///< fixations, always
    Organs,         ///< surrounding organs, always
    Insufflation,   ///< always
    Colonoscope,    ///< always
    Lesions,        ///< when the case has lesions
    Diverticula,    ///< when it has diverticula
    Adhesions,      ///< when it has adhesions (anchor springs)
    ResidualFluid,  ///< when any segment holds fluid
    ColitisMucosa,  ///< inflamed mucosa texture
    Snare,          ///< polypectomy only
};

[[nodiscard]] std::string_view componentName(SceneComponent component);

/// A place on the wall for the simulator: the segment, the arc length from
/// the anus to the place along the centreline (m) and the clock angle (rad).
struct ScenePlace {
    Segment segment = Segment::Rectum;
    double arcLength = 0;
    double angle = 0;
};

struct SceneLesion {
    ScenePlace place;
    double diameter = 0;      ///< m
    double youngModulus = 0;  ///< Pa
    Paris paris = Paris::Is;
    Histology histology = Histology::TubularLowGrade;
    Colour colour = Colour::Isochromatic;
    Surface surface = Surface::Smooth;
};

struct SceneDiverticulum {
    ScenePlace place;
    double diameter = 0;  ///< m
};

struct SceneSpec {
    geometry::AnatomyParameters anatomy;
    physics::TissueParameters tissue;
    physics::EnvironmentParameters environment;
    std::vector<SceneLesion> lesions;
    std::vector<SceneDiverticulum> diverticula;
    std::vector<ScenePlace> adhesions;
    std::array<double, kNumBowelRegions> residualStool{};  ///< fraction of mucosa, by BowelRegion
    std::array<double, kNumBowelRegions> residualFluid{};  ///< m^3, by BowelRegion
    ColitisExtent colitis = ColitisExtent::None;
    bool bleedingRisk = false;  ///< anticoagulated: matters for polypectomy
    std::vector<SceneComponent> components;

    [[nodiscard]] bool needs(SceneComponent component) const;
};

/// Translates a (validated) case. Throws params::ParameterError if a value is
/// outside the simulator's declared ranges, which a validated case never is.
[[nodiscard]] SceneSpec toScene(const Case& c);

}  // namespace colonosim::cases
