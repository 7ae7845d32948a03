#include "simcore/contact/LumenContact.h"

#include <algorithm>

namespace colonosim::contact {

namespace {
// Sections searched either side of the start. A node moves well under a
// section (12.6 mm on the default colon) per loop step, so its own last
// section and its neighbours suffice; consecutive nodes (20 mm apart) lie
// up to about two sections apart on an unpleated colon.
constexpr int kHistoryWindow = 1;
constexpr int kNeighbourWindow = 4;
}  // namespace

LumenContact::LumenContact(const geometry::ColonAnatomy& anatomy, const ContactParameters& parameters)
    : m_parameters(parameters), m_tube(anatomy)
{
    m_parameters.validate();
}

const std::vector<LumenNodeContact>& LumenContact::compute(const Eigen::Matrix3Xd& scope,
                                                           const Eigen::Matrix3Xd& scopeVelocities,
                                                           double radius, const Eigen::Matrix3Xd& wall,
                                                           const Eigen::Matrix3Xd& wallVelocities,
                                                           int addedAtBase, bool wallMoved)
{
    if (wallMoved) {
        m_tube.update(wall);
    }
    const auto n = static_cast<size_t>(scope.cols());
    // Each node's section at the last call, aligned from the tip.
    m_previousRing.resize(m_contacts.size());
    for (size_t j = 0; j < m_contacts.size(); ++j) {
        m_previousRing[j] = m_contacts[j].station.ring;
    }
    const bool history = addedAtBase != kNoHistory;
    m_contacts.resize(n);
    const int lastRing = m_tube.numRings() - 1;
    int neighbour = 0;
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p = scope.col(static_cast<Eigen::Index>(i));
        LumenNodeContact& c = m_contacts[i];
        const long j = static_cast<long>(i) - (history ? addedAtBase : 0);
        const bool known = history && j >= 0 && j < static_cast<long>(m_previousRing.size());
        c.station = known ? m_tube.locate(p, m_previousRing[static_cast<size_t>(j)], kHistoryWindow)
                          : m_tube.locate(p, neighbour, kNeighbourWindow);
        neighbour = c.station.ring;
        const LumenWallSample w = m_tube.wallAt(p, c.station);
        c.depth = w.distance + radius - w.wallRadius;
        c.normal = -w.radial;
        c.lever = w.distance;
        c.wallCentre = w.centre;
        c.wallAxis = w.axis;
        c.wallRadius = w.wallRadius;
        c.scopeRadius = radius;
        c.wallNodes = w.nodes;
        c.weights = w.weights;
        c.endCap = false;
        if (c.station.beyondEnd) {
            const double axial = m_tube.height(lastRing, p) + radius - m_tube.endHeight();
            if (axial > c.depth) {
                c.depth = axial;
                c.normal = -m_tube.axis(lastRing);
                c.wallNodes = {m_tube.apex(), m_tube.apex(), m_tube.apex(), m_tube.apex()};
                c.weights = {1.0, 0.0, 0.0, 0.0};
                c.endCap = true;
                c.lever = w.wallRadius;
                c.wallAxis = -m_tube.axis(lastRing);
                c.wallCentre = m_tube.centre(lastRing) + m_tube.endHeight() * m_tube.axis(lastRing);
            }
        }
        Eigen::Vector3d wallVelocity = Eigen::Vector3d::Zero();
        for (size_t k = 0; k < 4; ++k) {
            wallVelocity += c.weights[k] * wallVelocities.col(c.wallNodes[k]);
        }
        const Eigen::Vector3d relative = scopeVelocities.col(static_cast<Eigen::Index>(i)) - wallVelocity;
        c.slip = relative - relative.dot(c.normal) * c.normal;
    }
    return m_contacts;
}

double LumenNodeContact::depthAt(const Eigen::Vector3d& x, Eigen::Vector3d& n) const
{
    if (endCap) {
        n = wallAxis;
        return scopeRadius - (x - wallCentre).dot(wallAxis);
    }
    Eigen::Vector3d rho = x - wallCentre;
    rho -= rho.dot(wallAxis) * wallAxis;
    const double d = rho.norm();
    n = d > 0.0 ? Eigen::Vector3d(-rho / d) : normal;
    return d + scopeRadius - wallRadius;
}

Eigen::Vector3d LumenContact::friction(const LumenNodeContact& contact, double normalForce,
                                       double minStickVelocity) const
{
    const double speed = contact.slip.norm();
    const double stick = std::max(m_parameters.stickVelocity, minStickVelocity);
    return -m_parameters.frictionCoefficient * std::max(normalForce, 0.0) / std::max(speed, stick) *
           contact.slip;
}

}  // namespace colonosim::contact
