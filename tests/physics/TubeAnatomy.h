#pragma once
// A straight tube dressed as a colon anatomy, for physics tests that must not
// depend on the procedural layout: ring 0 is Fixed (anal verge), the next
// `anchoredRings` are Retroperitoneal, the rest hang on a mesentery whose
// root lies `mesenteryHeight` behind the tube (+y, posterior).

#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/physics/SpringCalibration.h"

#include <cmath>

namespace colonosim::physics::testing {

inline geometry::ColonAnatomy makeTubeAnatomy(const TubeResolution& tube, int anchoredRings = 2,
                                              double mesenteryHeight = 0.06)
{
    geometry::ColonAnatomy anatomy;
    anatomy.physicsMesh = makeStraightTube(tube);
    const int samples = 2 * tube.rings;
    const double length = (tube.rings - 1) * tube.ringSpacing;
    for (int s = 0; s < samples; ++s) {
        const double z = length * s / (samples - 1);
        anatomy.centreline.points.emplace_back(0.0, 0.0, z);
        anatomy.centreline.arcLength.push_back(z);
        anatomy.centreline.tangents.push_back(Eigen::Vector3d::UnitZ());
        anatomy.centreline.normals.push_back(Eigen::Vector3d::UnitX());
        anatomy.centreline.radius.push_back(tube.radius);
        anatomy.centreline.segment.push_back(geometry::Segment::Sigmoid);
    }
    for (int r = 0; r < tube.rings; ++r) {
        for (int k = 0; k < tube.nodesPerRing; ++k) {
            geometry::PhysicsNodeInfo info;
            info.segment = geometry::Segment::Sigmoid;
            info.arcLength = r * tube.ringSpacing;
            info.angle = 2.0 * M_PI * k / tube.nodesPerRing;
            info.attachment = r == 0               ? geometry::Attachment::Fixed
                              : r <= anchoredRings ? geometry::Attachment::Retroperitoneal
                                                   : geometry::Attachment::Mesenteric;
            info.mesenteryRoot = Eigen::Vector3d(0.0, tube.radius + mesenteryHeight, info.arcLength);
            anatomy.physicsNodes.push_back(info);
        }
    }
    return anatomy;
}

}  // namespace colonosim::physics::testing
