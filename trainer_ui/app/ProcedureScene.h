#pragma once
/// \file
/// Everything a procedure or a replay is built from, made once from the
/// session's case: the case itself (its XML is the case of record), the
/// anatomy (which the loop and the views share, so it outlives both), the
/// loop's settings, what the renderer puts on the wall, and the visual wall
/// mapped onto the physics mesh.

#include "case_generator/Case.h"
#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/geometry/MeshMapping.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/render/WallSurface.h"

#include <memory>
#include <optional>
#include <string>

namespace colonosim::app {

struct ProcedureScene {
    std::optional<cases::Case> theCase;  ///< none: the default colon
    geometry::ColonAnatomy anatomy;
    procedure::ProcedureSettings settings;
    render::WallSurface surface;
    geometry::MeshMapping mapping;  ///< physics nodes -> visual vertices
    int lesionsPresent = 0;
};

/// Builds the scene of `caseXml` (nullopt: the default colon). Throws
/// std::runtime_error with the reader's messages when the XML is not a valid case.
[[nodiscard]] std::shared_ptr<const ProcedureScene> buildScene(const std::optional<std::string>& caseXml);

}  // namespace colonosim::app
