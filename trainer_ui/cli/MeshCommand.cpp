/// \file
/// `colonosim mesh inspect FILE [--json]`: imports a patient-specific colon
/// surface (OBJ, STL, PLY; ASCII or binary), repairs or refuses it, and
/// computes its centreline.

#include "simcore/geometry/MeshImport.h"
#include "simcore/geometry/TubeCentreline.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace colonosim::cli {

int runMesh(std::span<char* const> args)
{
    const CommandLine line(args, {"--json", "--help"}, {});
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim mesh inspect FILE [--json]\n"
               "Imports an OBJ, STL or PLY colon surface (metres), reports repairs and its centreline.\n";
        return 0;
    }
    if (line.positional().size() != 2 || line.positional()[0] != "inspect") {
        throw UsageError("usage: colonosim mesh inspect FILE [--json]");
    }
    const geometry::ImportedMesh imported = geometry::importMesh(line.positional()[1]);
    const geometry::Centreline centreline = geometry::computeCentreline(imported.mesh);
    if (line.has("--json")) {
        nlohmann::json out;
        out["file"] = line.positional()[1];
        out["vertices"] = imported.mesh.numVertices();
        out["triangles"] = imported.mesh.numTriangles();
        out["repairs"] = imported.report.summary();
        out["open_ends"] = imported.report.numOpenEnds;
        out["centreline_length_m"] = centreline.length();
        out["centreline_points"] = centreline.numPoints();
        std::cout << out.dump(2) << '\n';
    } else {
        std::cout << line.positional()[1] << ": " << imported.mesh.numVertices() << " vertices, "
                  << imported.mesh.numTriangles() << " triangles\n"
                  << "repairs: " << imported.report.summary() << '\n'
                  << "centreline: " << centreline.length() << " m over " << centreline.numPoints()
                  << " points\n";
    }
    return 0;
}

}  // namespace colonosim::cli
