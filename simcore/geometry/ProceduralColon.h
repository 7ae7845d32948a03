#pragma once
/// \file
/// Builds a whole procedural colon from declared anatomy parameters.
///
/// Model: rings of nodes around the centreline of layoutColon(), node j of a
/// ring at c(s) + r (cos(theta_j) n(s) + sin(theta_j) b(s)) in the
/// rotation-minimising frame (n, b), theta_j = 2 pi j / numPerRing. Quads
/// between rings are split into two counter-clockwise triangles whose normals
/// point out of the lumen. The anal end is open; the cecal end is closed by a
/// flattened dome (depth half the cecal radius) ending in one apex node.
///
/// Physics mesh: physicsNodesPerRing nodes per ring, as many rings as give
/// about physicsTargetNodeCount nodes (de Visser et al. 2010: 1,872 nodes).
/// Visual mesh: visualNodesPerRing x visualRingCount vertices (>= 50,000 by
/// default) with haustral folds, r_v = r - D w(s) f(s) (1 - m(theta)) - T m(theta),
/// f(s) = ((1 + cos(2 pi s / h)) / 2)^6 a narrow fold every h metres, w(s)
/// fading the folds in above the rectum (the rectum has no haustra), and
/// m(theta) the three taeniae coli, Gaussian bands 120 degrees apart.
///
/// Attachments: the anal canal (first 2 cm) is Fixed; the rectum, descending
/// colon, both flexures and the non-mobile ascending colon are
/// Retroperitoneal; the sigmoid, transverse colon and the mobile fraction of
/// ascending colon + cecum (from the cecal end) hang on a mesentery, as does a
/// mobile descending colon. A mesenteric node's root lies posterior (+y) of
/// its centreline point by mesentery height + lumen radius.

#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/geometry/ColonAnatomy.h"

namespace colonosim::geometry {

/// Length of the anal canal whose nodes are Fixed, m.
inline constexpr double kAnalCanalLength = 0.02;

/// Builds centreline, both meshes, node information, landmarks and organs.
/// Throws params::ParameterError when `params` is invalid.
[[nodiscard]] ColonAnatomy buildProceduralColon(const AnatomyParameters& params);

}  // namespace colonosim::geometry
