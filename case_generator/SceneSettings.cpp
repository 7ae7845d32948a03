#include "case_generator/SceneSettings.h"

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

}  // namespace colonosim::cases
