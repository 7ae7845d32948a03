#include "simcore/contact/ScopeWallContact.h"

#include "simcore/contact/SegmentTriangle.h"

#include <algorithm>
#include <cmath>

namespace colonosim::contact {

namespace {
/// Contacts of one segment whose normals are closer than 45 degrees are one wall.
const double kSameWallCosine = std::sqrt(0.5);
}  // namespace

ScopeWallContact::ScopeWallContact(const geometry::TriangleMesh& wallMesh,
                                   const ContactParameters& parameters)
    : m_parameters(parameters), m_tree(wallMesh.vertices, wallMesh.triangles)
{
    m_parameters.validate();
    m_result.wallForces = Eigen::Matrix3Xd::Zero(3, wallMesh.numVertices());
}

const ContactResult& ScopeWallContact::compute(const Eigen::Matrix3Xd& scopePositions,
                                               const Eigen::Matrix3Xd& scopeVelocities,
                                               const Eigen::Matrix3Xd& previousPositions, double scopeRadius,
                                               const Eigen::Matrix3Xd& wallPositions,
                                               const Eigen::Matrix3Xd& wallVelocities)
{
    ContactResult& out = m_result;
    for (int node : out.wallNodesTouched) {
        out.wallForces.col(node).setZero();
    }
    if (out.wallForces.cols() != wallPositions.cols()) {
        out.wallForces = Eigen::Matrix3Xd::Zero(3, wallPositions.cols());
    }
    out.wallNodesTouched.clear();
    out.contacts.clear();
    out.crossings.clear();
    out.maxWallForce = 0.0;
    out.treeVisits = 0;
    const int numNodes = static_cast<int>(scopePositions.cols());
    out.scopeForces = Eigen::Matrix3Xd::Zero(3, numNodes);
    if (numNodes == 0) {
        return out;
    }

    m_tree.refit(wallPositions);
    const bool continuous = previousPositions.cols() == numNodes;
    const double maxStep =
        continuous ? (scopePositions - previousPositions).colwise().norm().maxCoeff() : 0.0;
    const int numSegments = std::max(numNodes - 1, 1);
    for (int s = 0; s < numSegments; ++s) {
        findSegmentContacts(s, scopePositions, continuous ? &previousPositions : nullptr, scopeRadius,
                            scopeRadius + maxStep, wallPositions);
        for (ScopeContact& c : m_segmentContacts) {
            applyLaw(c, scopeVelocities, wallVelocities);
            out.contacts.push_back(c);
        }
    }
    return out;
}

void ScopeWallContact::findSegmentContacts(int segment, const Eigen::Matrix3Xd& x,
                                           const Eigen::Matrix3Xd* previous, double radius, double reach,
                                           const Eigen::Matrix3Xd& wall)
{
    const int last = static_cast<int>(x.cols()) - 1;
    const int n0 = segment;
    const int n1 = std::min(segment + 1, last);
    const Eigen::Vector3d p0 = x.col(n0);
    const Eigen::Vector3d p1 = x.col(n1);
    m_candidates.clear();
    m_result.treeVisits += m_tree.queryCapsule(p0, p1, reach, m_candidates);

    m_segmentContacts.clear();
    const auto& triangles = m_tree.triangles();
    for (int tri : m_candidates) {
        const auto& v = triangles[static_cast<size_t>(tri)];
        const Eigen::Vector3d a = wall.col(v[0]);
        const Eigen::Vector3d b = wall.col(v[1]);
        const Eigen::Vector3d c = wall.col(v[2]);
        const SegmentTriangleProximity prox = segmentTriangleProximity(p0, p1, a, b, c, radius);
        if (prox.found && prox.signedDistance < radius) {
            ScopeContact contact;
            contact.segment = segment;
            contact.triangle = tri;
            contact.segmentParam = n1 == n0 ? 0.0 : prox.segmentParam;
            contact.barycentric = prox.barycentric;
            contact.depth = radius - prox.signedDistance;
            contact.normal = prox.normal;
            contact.point = prox.wallPoint;
            m_segmentContacts.push_back(contact);
        }
        if (previous == nullptr) {
            continue;
        }
        // Each node's motion is swept once: node `segment`, and the last node with the last segment.
        for (int node = n0; node <= n1; ++node) {
            if (node != segment && !(node == last && segment == last - 1)) {
                continue;
            }
            const WallCrossing crossing = pointCrossesTriangle(previous->col(node), x.col(node), a, b, c);
            if (!crossing.crossed) {
                continue;
            }
            m_result.crossings.push_back({node, tri, crossing.point, crossing.normal});
            ScopeContact contact;
            contact.segment = segment;
            contact.triangle = tri;
            contact.segmentParam = node == n0 ? 0.0 : 1.0;
            contact.barycentric = crossing.barycentric;
            contact.depth = radius - (x.col(node) - crossing.point).dot(crossing.normal);
            contact.normal = crossing.normal;
            contact.point = crossing.point;
            contact.crossed = true;
            m_segmentContacts.push_back(contact);
        }
    }
    // Deepest first; then keep one contact per wall direction.
    std::sort(m_segmentContacts.begin(), m_segmentContacts.end(),
              [](const ScopeContact& l, const ScopeContact& r) { return l.depth > r.depth; });
    size_t kept = 0;
    for (size_t i = 0; i < m_segmentContacts.size(); ++i) {
        bool sameWall = false;
        for (size_t k = 0; k < kept && !sameWall; ++k) {
            sameWall = m_segmentContacts[i].normal.dot(m_segmentContacts[k].normal) > kSameWallCosine;
        }
        if (!sameWall) {
            m_segmentContacts[kept++] = m_segmentContacts[i];
        }
    }
    m_segmentContacts.resize(kept);
}

void ScopeWallContact::applyLaw(ScopeContact& contact, const Eigen::Matrix3Xd& scopeVelocities,
                                const Eigen::Matrix3Xd& wallVelocities)
{
    ContactResult& out = m_result;
    const int last = static_cast<int>(scopeVelocities.cols()) - 1;
    const int n0 = contact.segment;
    const int n1 = std::min(contact.segment + 1, last);
    const double t = contact.segmentParam;
    const auto& tri = m_tree.triangles()[static_cast<size_t>(contact.triangle)];
    const Eigen::Vector3d& b = contact.barycentric;
    const Eigen::Vector3d vScope = (1.0 - t) * scopeVelocities.col(n0) + t * scopeVelocities.col(n1);
    const Eigen::Vector3d vWall = b[0] * wallVelocities.col(tri[0]) + b[1] * wallVelocities.col(tri[1]) +
                                  b[2] * wallVelocities.col(tri[2]);
    const Eigen::Vector3d vRel = vScope - vWall;
    const Eigen::Vector3d& n = contact.normal;
    const double vn = vRel.dot(n);
    const double fn =
        std::max(0.0, m_parameters.contactStiffness * contact.depth - m_parameters.contactDamping * vn);
    const Eigen::Vector3d vt = vRel - vn * n;
    const double speed = vt.norm();
    const Eigen::Vector3d ft =
        -m_parameters.frictionCoefficient * fn / std::max(speed, m_parameters.stickVelocity) * vt;
    contact.normalForce = fn;
    contact.frictionForce = ft;
    const Eigen::Vector3d force = fn * n + ft;
    out.scopeForces.col(n0) += (1.0 - t) * force;
    out.scopeForces.col(n1) += t * force;
    for (int k = 0; k < 3; ++k) {
        out.wallForces.col(tri[static_cast<size_t>(k)]) -= b[k] * force;
        out.wallNodesTouched.push_back(tri[static_cast<size_t>(k)]);
    }
    out.maxWallForce = std::max(out.maxWallForce, force.norm());
}

void pushBackCrossedNodes(const ContactResult& result, Eigen::Matrix3Xd& positions,
                          Eigen::Matrix3Xd& velocities, double margin)
{
    for (const NodeCrossing& c : result.crossings) {
        positions.col(c.scopeNode) = c.point + margin * c.normal;
        const double vn = velocities.col(c.scopeNode).dot(c.normal);
        if (vn < 0.0) {
            velocities.col(c.scopeNode) -= vn * c.normal;
        }
    }
}

}  // namespace colonosim::contact
