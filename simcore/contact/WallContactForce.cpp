#include "simcore/contact/WallContactForce.h"

#include <algorithm>

namespace colonosim::contact {

WallContactForce::WallContactForce(const geometry::TriangleMesh& wallMesh,
                                   const ContactParameters& parameters, int numWallNodes)
    : m_mesh(wallMesh), m_parameters(parameters), m_numWallNodes(numWallNodes)
{
    m_parameters.validate();
}

void WallContactForce::setContacts(const std::vector<ScopeContact>& contacts,
                                   const std::vector<Eigen::Vector3d>& scopeAxisPoints, double radius)
{
    std::vector<WallContactPoint> rigid;
    for (const Eigen::Vector3d& axisPoint : scopeAxisPoints) {
        rigid.push_back({axisPoint, m_parameters.contactStiffness, 0.0, 1.0});
    }
    setContacts(contacts, rigid, radius);
}

void WallContactForce::setContacts(const std::vector<ScopeContact>& contacts,
                                   const std::vector<WallContactPoint>& points, double radius)
{
    m_radius = radius;
    m_contacts.clear();
    for (size_t k = 0; k < contacts.size() && k < points.size(); ++k) {
        const ScopeContact& c = contacts[k];
        const WallContactPoint& p = points[k];
        const double stiffness = std::clamp(p.stiffness, 0.0, m_parameters.contactStiffness);
        m_contacts.push_back(Active{m_mesh.triangles[static_cast<size_t>(c.triangle)], c.barycentric,
                                    c.normal, p.axisPoint, -p.frictionScale * c.frictionForce, stiffness,
                                    p.depthOffset});
    }
}

double WallContactForce::depth(const Active& c, const physics::Positions& x) const
{
    const Eigen::Vector3d wall = c.barycentric[0] * x.col(c.vertices[0]) +
                                 c.barycentric[1] * x.col(c.vertices[1]) +
                                 c.barycentric[2] * x.col(c.vertices[2]);
    return m_radius - (c.axisPoint - wall).dot(c.normal) + c.depthOffset;
}

void WallContactForce::addForce(const physics::Positions& x, physics::Forces& f) const
{
    for (const Active& c : m_contacts) {
        const double fn = std::max(0.0, c.stiffness * depth(c, x));
        for (int m = 0; m < 3; ++m) {
            f.col(c.vertices[static_cast<size_t>(m)]) += c.barycentric[m] * (c.friction - fn * c.normal);
        }
    }
}

void WallContactForce::addDampingForce(const physics::Positions& x, const physics::Velocities& v,
                                       physics::Forces& f) const
{
    for (const Active& c : m_contacts) {
        if (depth(c, x) <= 0.0) {
            continue;
        }
        const Eigen::Vector3d wallVelocity = c.barycentric[0] * v.col(c.vertices[0]) +
                                             c.barycentric[1] * v.col(c.vertices[1]) +
                                             c.barycentric[2] * v.col(c.vertices[2]);
        // The wall moving outward (against n) deepens the contact: the force
        // -c_n (v_w . n) n on the wall resists it, split by b.
        const double damping = -m_parameters.contactDamping * wallVelocity.dot(c.normal);
        for (int m = 0; m < 3; ++m) {
            f.col(c.vertices[static_cast<size_t>(m)]) += c.barycentric[m] * damping * c.normal;
        }
    }
}

void WallContactForce::addStiffnessProduct(const physics::Positions& x, const Eigen::Matrix3Xd& dx,
                                           Eigen::Matrix3Xd& df) const
{
    for (const Active& c : m_contacts) {
        if (depth(c, x) <= 0.0) {
            continue;
        }
        const Eigen::Vector3d dw = c.barycentric[0] * dx.col(c.vertices[0]) +
                                   c.barycentric[1] * dx.col(c.vertices[1]) +
                                   c.barycentric[2] * dx.col(c.vertices[2]);
        const Eigen::Vector3d row = c.stiffness * dw.dot(c.normal) * c.normal;
        for (int m = 0; m < 3; ++m) {
            df.col(c.vertices[static_cast<size_t>(m)]) -= c.barycentric[m] * row;
        }
    }
}

void WallContactForce::addDampingProduct(const physics::Positions& x, const Eigen::Matrix3Xd& dv,
                                         Eigen::Matrix3Xd& df) const
{
    for (const Active& c : m_contacts) {
        if (depth(c, x) <= 0.0) {
            continue;
        }
        const Eigen::Vector3d dw = c.barycentric[0] * dv.col(c.vertices[0]) +
                                   c.barycentric[1] * dv.col(c.vertices[1]) +
                                   c.barycentric[2] * dv.col(c.vertices[2]);
        const Eigen::Vector3d row = m_parameters.contactDamping * dw.dot(c.normal) * c.normal;
        for (int m = 0; m < 3; ++m) {
            df.col(c.vertices[static_cast<size_t>(m)]) -= c.barycentric[m] * row;
        }
    }
}

void WallContactForce::addStiffnessBound(const physics::Positions& /*x*/, Eigen::VectorXd& kRow,
                                         Eigen::VectorXd& cRow) const
{
    // Row m of K holds k_c b_m b_l for l = 1..3: at most k_c b_m <= k_c. A
    // contact may appear at any wall node, so every node reserves it.
    for (int node = 0; node < m_numWallNodes; ++node) {
        kRow[node] += m_parameters.contactStiffness;
        cRow[node] += m_parameters.contactDamping;
    }
}

double WallContactForce::potentialEnergy(const physics::Positions& x) const
{
    double energy = 0.0;
    for (const Active& c : m_contacts) {
        const double d = std::max(0.0, depth(c, x));
        energy += 0.5 * c.stiffness * d * d;
    }
    return energy;
}

}  // namespace colonosim::contact
