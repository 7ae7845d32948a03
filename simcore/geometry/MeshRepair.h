#pragma once
/// \file
/// Checks and repairs a triangle soup that should be one colon-like tube.
/// Repair or refuse, never crash:
/// 1. any non-finite coordinate -> refuse;
/// 2. vertices closer than 1e-9 x the bounding-box diagonal are merged;
/// 3. faces with repeated indices, zero area or duplicating another face are
///    dropped and counted;
/// 4. an edge shared by more than 2 faces -> refuse (non-manifold);
/// 5. more than one connected component -> refuse;
/// 6. faces are re-oriented consistently by breadth-first flipping across
///    shared edges; a conflict means a non-orientable surface -> refuse;
/// 7. boundary loops: a tube has at most two open ends (the loops at least
///    half as long as the longest); any other loop shorter than
///    kMaxHoleFraction x the longest is a hole, filled by a fan around its
///    centroid; a longer extra loop -> refuse;
/// 8. the whole surface is flipped if its normals point into the lumen
///    (negative signed volume once the open ends are virtually capped).

#include "simcore/geometry/TriangleMesh.h"

#include <stdexcept>
#include <string>

namespace colonosim::geometry {

/// Refusal of an input mesh: "FILE: what (field/value/allowed)".
class MeshImportError : public std::runtime_error {
public:
    explicit MeshImportError(const std::string& message) : std::runtime_error(message) {}
};

inline constexpr double kMaxHoleFraction = 0.5;

struct MeshRepairReport {
    int numInputVertices = 0;
    int numInputTriangles = 0;
    int numMergedVertices = 0;
    int numDegenerateFacesRemoved = 0;
    int numDuplicateFacesRemoved = 0;
    int numFacesReoriented = 0;
    bool globallyFlipped = false;
    int numOpenEnds = 0;
    int numHolesFilled = 0;

    [[nodiscard]] bool anyRepair() const
    {
        return numMergedVertices > 0 || numDegenerateFacesRemoved > 0 || numDuplicateFacesRemoved > 0 ||
               numFacesReoriented > 0 || globallyFlipped || numHolesFilled > 0;
    }
    [[nodiscard]] std::string summary() const;
};

/// Repairs `mesh` in place; `label` (the file name) prefixes every error.
MeshRepairReport repairTubeMesh(TriangleMesh& mesh, const std::string& label);

}  // namespace colonosim::geometry
