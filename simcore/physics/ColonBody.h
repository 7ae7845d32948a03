#pragma once
/// \file
/// Builds the colon's tissue body from an anatomy (CSIRO paper §2.4, NASA
/// paper "soft-tissue modeling"): every physics-mesh vertex becomes a mass,
/// every edge a structural or shear spring, and every pair of triangles
/// sharing an edge a spring between their opposite vertices (shear across a
/// quad's diagonal, bending otherwise: the "torsion between adjacent triangles").
///
/// Spring constants follow Van Gelder (1998), k_e = alpha E t A_e / |e|^2
/// with A_e the area of the triangles on the edge, scaled per family:
/// structural springs by the calibrated factors alpha_axial and
/// alpha_circumferential (SpringCalibration.h), shear and bending springs by
/// their declared ratios times sqrt(alpha_axial alpha_circumferential).
/// Node masses: rho t times a third of the adjacent triangles' area.
/// Fixations: Fixed nodes are held; retroperitoneal nodes are anchored to
/// their rest positions; mesenteric nodes hang on a Mesentery tether of
/// stiffness k = E_m t_m (A_i / 2 pi r) / L to their root. Every spring is
/// damped with c = beta k (by default on the whole relative velocity of its
/// nodes, `tissue.transverseDampingRatio`: SpringSet.h), and the surrounding
/// viscera add a drag -alpha m v.
/// Environment: gravity by patient position,
/// insufflation pressure, organs as non-penetrable shapes.

#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/physics/AnchorSprings.h"
#include "simcore/physics/InsufflationPressure.h"
#include "simcore/physics/LumenSelfContact.h"
#include "simcore/physics/Mesentery.h"
#include "simcore/physics/SpringSet.h"
#include "simcore/physics/TissueBody.h"
#include "simcore/physics/TissueParameters.h"

#include <vector>

namespace colonosim::physics {

/// Scale factors on the Van Gelder structural stiffness (1), found by
/// calibrateWallStiffness().
struct StiffnessCalibration {
    double axial = 1.0;
    double circumferential = 1.0;
};

struct ColonBody {
    TissueBody body;
    SpringSet* springs = nullptr;
    Mesentery* mesentery = nullptr;
    AnchorSprings* retroperitoneal = nullptr;
    AnchorSprings* adhesions = nullptr;
    InsufflationPressure* insufflation = nullptr;
    LumenSelfContact* selfContact = nullptr;  ///< null when the mesh has no rings or k = 0
    /// Spring-connected neighbours of each node (for the active region).
    std::vector<std::vector<int>> neighbours;
};

struct ColonBodyOptions {
    bool withGravity = true;
    bool withInsufflation = true;
    bool withOrgans = true;
    std::vector<int> adhesionNodes;  ///< extra anchors (prior surgery)
};

/// Validates the parameters (throws ParameterError) and builds the body.
[[nodiscard]] ColonBody buildColonBody(const geometry::ColonAnatomy& anatomy, const TissueParameters& tissue,
                                       const EnvironmentParameters& environment,
                                       const StiffnessCalibration& calibration,
                                       const ColonBodyOptions& options = {});

/// Wall springs and masses only (no fixations or environment), for a mesh
/// whose local axis at each vertex is `axis` (unit); used by the builder and
/// by the calibration on a straight tube.
void addWallSprings(const geometry::TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& axis,
                    const TissueParameters& tissue, const StiffnessCalibration& calibration,
                    SpringSet& springs);
[[nodiscard]] Eigen::VectorXd wallNodeMasses(const geometry::TriangleMesh& mesh,
                                             const TissueParameters& tissue);

}  // namespace colonosim::physics
