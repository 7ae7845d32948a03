#pragma once
/// \file
/// One colon anatomy: centreline, low-resolution physics mesh, high-resolution
/// visual mesh, per-node anatomical information, landmarks and surrounding
/// organs. Produced by buildProceduralColon() (or from an imported mesh) and
/// consumed by the physics builder and, later, by the renderer.
///
/// Coordinates: patient LPS, metres, origin at the anal verge.
/// x points to the patient's left, y posterior, z superior (cranial).

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/ImplicitShape.h"
#include "simcore/geometry/Segment.h"
#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace colonosim::geometry {

/// Anatomical information for one physics-mesh node.
struct PhysicsNodeInfo {
    Segment segment = Segment::Rectum;
    Attachment attachment = Attachment::Mesenteric;
    double arcLength = 0.0;  ///< position along the centreline from the anus, m
    double angle = 0.0;      ///< clock-face angle around the centreline, rad
    /// Where this node's mesentery (mobile nodes) or retroperitoneal binding
    /// (anchored nodes) attaches to the posterior abdominal wall, m.
    Eigen::Vector3d mesenteryRoot = Eigen::Vector3d::Zero();
};

struct Landmark {
    std::string name;  ///< "ileocecal_valve", "appendiceal_orifice"
    Segment segment = Segment::Cecum;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< on the wall, m
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();    ///< into the lumen
    int nearestPhysicsNode = -1;
};

struct ColonAnatomy {
    Centreline centreline;
    TriangleMesh physicsMesh;                   ///< ~1,900 nodes by default
    std::vector<PhysicsNodeInfo> physicsNodes;  ///< one per physics-mesh vertex
    TriangleMesh visualMesh;                    ///< >= 50,000 vertices by default
    std::vector<Landmark> landmarks;
    std::vector<ImplicitShape> organs;
};

}  // namespace colonosim::geometry
