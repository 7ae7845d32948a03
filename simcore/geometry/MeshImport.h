#pragma once
/// \file
/// Imports a colon surface from OBJ, STL or PLY (ASCII or binary) through
/// assimp, then checks and repairs it as a tube (MeshRepair.h). Units are
/// taken as metres. Errors are MeshImportError "FILE: what (field/value/allowed)":
/// unknown extension, missing or empty file, unreadable bytes, non-finite
/// coordinates, non-manifold edges, several components, a non-orientable
/// surface or a hole too large to fill.

#include "simcore/geometry/MeshRepair.h"
#include "simcore/geometry/TriangleMesh.h"

#include <filesystem>

namespace colonosim::geometry {

struct ImportedMesh {
    TriangleMesh mesh;
    MeshRepairReport report;
};

[[nodiscard]] ImportedMesh importMesh(const std::filesystem::path& path);

}  // namespace colonosim::geometry
