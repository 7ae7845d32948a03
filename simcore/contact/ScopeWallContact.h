#pragma once
/// \file
/// Contact between the colonoscope and the colon wall, one step at a time.
///
/// Geometry: the scope is a polyline of capsules of radius r (segment i joins
/// nodes i and i + 1); the wall is the physics mesh, searched through a
/// BoundingSphereTree refit every step and restricted to the enabled (active)
/// triangles; SegmentTriangle.h gives the depth = r - d of each pair.
/// Each segment keeps its deepest contact per wall direction (normals more
/// than 45 degrees apart count as different walls), so the force does not
/// grow with the number of triangles under one segment.
///
/// Law (penalty with regularised Coulomb friction), per contact with inward
/// normal n, scope point at segment parameter t and wall point at barycentric
/// (b0, b1, b2), v_rel = v_scope(t) - v_wall(b):
///   f_n = max(0, k_c depth - c_n v_rel . n)
///   v_t = v_rel - (v_rel . n) n
///   f_t = -mu f_n v_t / max(|v_t|, v_s)
/// so |f_t| <= mu f_n, equal to mu f_n when sliding faster than v_s, viscous
/// below it (stick regularised by the velocity scale v_s). The force
/// F = f_n n + f_t acts on the scope, split (1 - t, t) between the segment's
/// end nodes, and -F on the wall, split by b: forces sum to zero.
/// Parameters: ContactParameters.h.
///
/// No tunnelling: when previous scope positions are given, each node's motion
/// [x_prev, x] is tested against every enabled triangle within r + max
/// displacement of its segment (exact segment-triangle intersection, so the
/// guarantee does not depend on the speed or the step). A node that passed
/// through a triangle from the lumen side becomes a deep contact
/// (depth = r - d, d < 0, on that triangle) and is reported in `crossings`;
/// pushBackCrossedNodes() moves it back to the crossing point on the lumen
/// side. Guarantee: a scope node never ends a step outside a triangle it
/// crossed, for any speed, against the wall's current positions (the wall's
/// own motion during one step, about v_wall dt, is not swept). Not covered:
/// a wall edge passing between two nodes through a segment's interior,
/// which first has to overcome the penalty of depth r.

#include "simcore/contact/BoundingSphereTree.h"
#include "simcore/contact/ContactParameters.h"
#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::contact {

struct ScopeContact {
    int segment = -1;           ///< scope segment (nodes segment, segment + 1)
    int triangle = -1;          ///< wall triangle
    double segmentParam = 0.0;  ///< t along the segment
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
    double depth = 0.0;                                       ///< r - d, m
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();         ///< unit, into the lumen (pushes the scope)
    double normalForce = 0.0;                                 ///< f_n >= 0, N
    Eigen::Vector3d frictionForce = Eigen::Vector3d::Zero();  ///< f_t on the scope, N
    Eigen::Vector3d point = Eigen::Vector3d::Zero();          ///< wall point, m
    bool crossed = false;                                     ///< found by continuous detection
};

struct NodeCrossing {
    int scopeNode = -1;
    int triangle = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< where the motion met the wall, m
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit, into the lumen
};

struct ContactResult {
    Eigen::Matrix3Xd scopeForces;       ///< 3 x numScopeNodes, N
    Eigen::Matrix3Xd wallForces;        ///< 3 x numWallNodes, N (zero off wallNodesTouched)
    std::vector<int> wallNodesTouched;  ///< wall nodes with a contact force (may repeat)
    std::vector<ScopeContact> contacts;
    std::vector<NodeCrossing> crossings;
    double maxWallForce = 0.0;  ///< largest |F| of one contact, N ("maximum wall force")
    int treeVisits = 0;         ///< bounding-sphere nodes visited this step
};

class ScopeWallContact {
public:
    /// Throws params::ParameterError when `parameters` is invalid.
    ScopeWallContact(const geometry::TriangleMesh& wallMesh, const ContactParameters& parameters = {});

    [[nodiscard]] const ContactParameters& parameters() const { return m_parameters; }
    [[nodiscard]] BoundingSphereTree& tree() { return m_tree; }
    [[nodiscard]] const BoundingSphereTree& tree() const { return m_tree; }

    /// Restricts the search to triangles with an awake vertex (one flag per wall node).
    void setActiveNodes(std::span<const std::uint8_t> awake) { m_tree.setEnabledFromNodes(awake); }
    void enableAll() { m_tree.enableAll(); }

    /// One step: refits the tree to `wallPositions`, finds the contacts of the
    /// scope polyline (3 x n positions and velocities; `previousPositions`
    /// empty or 3 x n for continuous detection) and computes the forces.
    const ContactResult& compute(const Eigen::Matrix3Xd& scopePositions,
                                 const Eigen::Matrix3Xd& scopeVelocities,
                                 const Eigen::Matrix3Xd& previousPositions, double scopeRadius,
                                 const Eigen::Matrix3Xd& wallPositions,
                                 const Eigen::Matrix3Xd& wallVelocities);
    [[nodiscard]] const ContactResult& result() const { return m_result; }

private:
    void findSegmentContacts(int segment, const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd* previous,
                             double radius, double reach, const Eigen::Matrix3Xd& wall);
    void applyLaw(ScopeContact& contact, const Eigen::Matrix3Xd& scopeVelocities,
                  const Eigen::Matrix3Xd& wallVelocities);

    ContactParameters m_parameters;
    BoundingSphereTree m_tree;
    ContactResult m_result;
    std::vector<int> m_candidates;
    std::vector<ScopeContact> m_segmentContacts;
};

/// Moves every crossed node back to its crossing point plus `margin` along
/// the inward normal and removes its outward normal velocity.
void pushBackCrossedNodes(const ContactResult& result, Eigen::Matrix3Xd& positions,
                          Eigen::Matrix3Xd& velocities, double margin = 1e-4);

}  // namespace colonosim::contact
