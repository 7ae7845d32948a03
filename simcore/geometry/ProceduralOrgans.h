#pragma once
/// \file
/// The organs around a procedural colon, as implicit shapes placed relative
/// to the colon's stations (ColonLayout), so that they scale with the body:
/// - abdominal cavity (KeepInside ellipsoid) around every rest node, with a
///   margin of kCavityMargin;
/// - liver above the hepatic flexure (right upper quadrant), spleen above
///   and lateral to the splenic flexure (left upper quadrant);
/// - both kidneys, retroperitoneal, posterior to the ascending and descending
///   colon; the lumbar spine and sacrum as a posterior midline capsule;
/// - the bladder in the anterior pelvis, in front of the rectum.
/// Typical adult sizes (liver ~ 20 x 15 x 12 cm, spleen ~ 12 x 7 x 4 cm,
/// kidney ~ 11 x 6 x 4 cm, vertebral body ~ 5 cm) are textbook anatomy, not
/// from a reference table. An organ whose typical position would touch a rest
/// node is slid away (liver and spleen cranially, kidneys and spine
/// posteriorly, bladder anteriorly) until every rest node clears it by
/// kOrganClearance: the colon is never born penetrating an organ.

#include "simcore/geometry/ColonLayout.h"
#include "simcore/geometry/ImplicitShape.h"
#include "simcore/geometry/TriangleMesh.h"

#include <vector>

namespace colonosim::geometry {

inline constexpr double kOrganClearance = 0.005;  ///< m
inline constexpr double kCavityMargin = 0.02;     ///< m

[[nodiscard]] std::vector<ImplicitShape> placeProceduralOrgans(const ColonLayout& layout,
                                                               const TriangleMesh& restMesh);

}  // namespace colonosim::geometry
