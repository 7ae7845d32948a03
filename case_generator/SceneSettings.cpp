#include "case_generator/SceneSettings.h"

#include "case_generator/Quantity.h"

namespace colonosim::cases {

procedure::ProcedureSettings procedureSettings(const SceneSpec& scene)
{
    procedure::ProcedureSettings settings;
    settings.tissue = scene.tissue;
    settings.environment = scene.environment;
    for (const SceneLesion& lesion : scene.lesions) {
        settings.lesions.push_back(procedure::WallSite{lesion.place.arcLength, lesion.place.angle});
    }
    for (const ScenePlace& adhesion : scene.adhesions) {
        settings.adhesions.push_back(procedure::WallSite{adhesion.arcLength, adhesion.angle});
    }
    return settings;
}

std::optional<std::string> cecumOutOfReach(const Case& c)
{
    const double scope = procedure::ProcedureSettings{}.scope.workingLength;
    const double colon = c.anatomy.colonLength();
    if (colon <= scope) {
        return std::nullopt;
    }
    const std::string why =
        "the simulated colon pleats onto the shaft by a few centimetres only, so its cecum is out of the "
        "scope's reach";
    return "the colon is " + formatFixed(colon, 3) + " m long, longer than the scope's " +
           formatFixed(scope, 2) + " m working length; " + why;
}

}  // namespace colonosim::cases
