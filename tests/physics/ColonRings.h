#pragma once
// The lumen's rings of a procedural colon (LumenSelfContact.h), for tests that
// press two parts of the default colon together: the ring nearest a place
// along the colon, and a ring's centre at given positions.

#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/physics/LumenSelfContact.h"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace colonosim::physics::testing {

/// The ring of `anatomy`'s physics mesh whose rest arc length is nearest `arc` (m).
inline LumenSelfContact::Ring ringNearest(const geometry::ColonAnatomy& anatomy, double arc)
{
    std::vector<double> arcs;
    for (const auto& node : anatomy.physicsNodes) {
        arcs.push_back(node.arcLength);
    }
    const std::vector<LumenSelfContact::Ring> rings = lumenRings(anatomy.physicsMesh.vertices, arcs);
    size_t best = 0;
    for (size_t i = 0; i < rings.size(); ++i) {
        if (std::abs(rings[i].arcLength - arc) < std::abs(rings[best].arcLength - arc)) {
            best = i;
        }
    }
    return rings[best];
}

/// The mean of the ring's nodes at `x`, m.
inline Eigen::Vector3d ringCentre(const Positions& x, const LumenSelfContact::Ring& ring)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int node : ring.nodes) {
        sum += x.col(node);
    }
    return sum / static_cast<double>(ring.nodes.size());
}

}  // namespace colonosim::physics::testing
