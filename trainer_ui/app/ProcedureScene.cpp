#include "trainer_ui/app/ProcedureScene.h"
#include "trainer_ui/cli/CaseArgument.h"

#include "case_generator/CaseReader.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/ProceduralColon.h"
#include "trainer_ui/cli/CaseArgument.h"
#include "trainer_ui/cli/SceneFindings.h"

#include <stdexcept>

namespace colonosim::app {

std::shared_ptr<const ProcedureScene> buildScene(const std::optional<std::string>& caseXml)
{
    auto scene = std::make_shared<ProcedureScene>();
    geometry::AnatomyParameters anatomyParameters;
    render::WallFindings findings;
    if (caseXml) {
        cases::ReadResult read = cases::readCase(*caseXml, "case");
        if (!read.ok()) {
            std::string message = "the session's case cannot be read:";
            for (const std::string& error : read.errors) {
                message += "\n" + error;
            }
            throw std::runtime_error(message);
        }
        const cases::SceneSpec spec = cases::toScene(*read.value);
        anatomyParameters = spec.anatomy;
        scene->settings = cases::procedureSettings(spec);
        findings = cli::findingsOf(spec);
        scene->lesionsPresent = static_cast<int>(read.value->lesions.size());
        scene->theCase = std::move(read.value);
    }
    scene->anatomy = geometry::buildProceduralColon(anatomyParameters);
    scene->surface = render::buildWallSurface(scene->anatomy.visualMesh, scene->anatomy.centreline, findings);
    scene->mapping = geometry::MeshMapping(scene->anatomy.physicsMesh, scene->surface.rest.vertices);
    return scene;
}

}  // namespace colonosim::app
