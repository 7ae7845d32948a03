#include "simcore/contact/LumenContact.h"

#include <algorithm>
#include <cmath>

namespace colonosim::contact {

namespace {
// Sections searched either side of the start. A node moves well under a
// section (12.6 mm on the default colon) per loop step, so its own last
// section and its neighbours suffice; consecutive nodes (20 mm apart) lie
// up to about two sections apart on an unpleated colon.
constexpr int kHistoryWindow = 1;
constexpr int kNeighbourWindow = 4;
// Sections searched for the wall that holds a node whose walk was held at a
// fold (its centre outside its own section's wall): 16 sections, 20 cm of
// colon at rest. The expert's withdrawal on the default colon, before this
// search, held the tip's station at section 15 while the tip lay in
// sections 3-6: 9-12 sections away.
constexpr int kHeldWindow = 16;
/// m: the closed end's cone is taken at least this high (a flattened cap
/// still turns the normal onto the axis).
constexpr double kMinCapHeight = 1e-3;
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
    const bool pleats = std::lround(m_parameters.pleatSearch) != 0;
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p = scope.col(static_cast<Eigen::Index>(i));
        LumenNodeContact& c = m_contacts[i];
        const long j = static_cast<long>(i) - (history ? addedAtBase : 0);
        const bool known = history && j >= 0 && j < static_cast<long>(m_previousRing.size());
        c.station = known ? m_tube.locate(p, m_previousRing[static_cast<size_t>(j)], kHistoryWindow)
                          : m_tube.locate(p, neighbour, kNeighbourWindow);
        LumenWallSample w = m_tube.wallAt(p, c.station);
        if (w.distance > w.wallRadius && !c.station.beyondEnd && !c.station.beforeStart) {
            // The walk was held at a fold: on towards the neighbour's
            // section (or, searching through pleats, on the far side along
            // the shaft's path from the neighbour), a section's wall may
            // hold the node.
            const bool throughPleats = pleats && i > 0;
            const Eigen::Vector3d base =
                throughPleats ? Eigen::Vector3d(scope.col(static_cast<Eigen::Index>(i) - 1)) : p;
            LumenStation held;
            if (m_tube.findHolding(p, c.station.ring, neighbour, kHeldWindow, held,
                                   throughPleats ? &base : nullptr, radius)) {
                c.station = held;
                w = m_tube.wallAt(p, c.station);
            }
        }
        neighbour = c.station.ring;
        c.depth = w.distance + radius - w.wallRadius;
        c.normal = -w.radial;
        c.lever = w.distance;
        c.wallCentre = w.centre;
        c.wallAxis = w.axis;
        c.wallRadius = w.wallRadius;
        c.scopeRadius = radius;
        c.wallNodes = w.nodes;
        c.weights = w.weights;
        c.endCap = c.station.beyondEnd;
        if (c.endCap) {
            // The side wall's part on the dome ring and the cone's on the
            // apex and the same two nodes, blended as the depths are.
            c.capCentre = m_tube.centre(lastRing);
            c.capAxis = m_tube.axis(lastRing);
            c.capHeight = std::max(m_tube.endHeight(), kMinCapHeight);
            Eigen::Vector3d n;
            double side = 0.0;
            double toApex = 0.0;
            c.depth = c.depthAt(p, n, side, toApex);
            c.normal = n;
            const double ring = w.weights[2] + w.weights[3];
            const double f = ring > 0.0 ? w.weights[3] / ring : 0.0;
            const double onRing = 1.0 - (1.0 - side) * toApex;
            c.wallNodes = {w.nodes[2], w.nodes[3], m_tube.apex(), m_tube.apex()};
            c.weights = {onRing * (1.0 - f), onRing * f, 1.0 - onRing, 0.0};
            c.lever = w.wallRadius;
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

void LumenContact::addSurfaceSpin(const Eigen::Matrix3Xd& spin)
{
    const auto n = std::min(static_cast<Eigen::Index>(m_contacts.size()), spin.cols());
    for (Eigen::Index i = 0; i < n; ++i) {
        LumenNodeContact& c = m_contacts[static_cast<size_t>(i)];
        // The surface point touching the wall lies r from the axis, against
        // the normal: it moves at w x (-r n) relative to the axis.
        const Eigen::Vector3d surface = -c.scopeRadius * spin.col(i).cross(c.normal);
        c.slip += surface - surface.dot(c.normal) * c.normal;
    }
}

double LumenNodeContact::depthAt(const Eigen::Vector3d& x, Eigen::Vector3d& n) const
{
    double side = 0.0;
    double toApex = 0.0;
    return depthAt(x, n, side, toApex);
}

double LumenNodeContact::depthAt(const Eigen::Vector3d& x, Eigen::Vector3d& n, double& side,
                                 double& toApex) const
{
    Eigen::Vector3d rho = x - wallCentre;
    rho -= rho.dot(wallAxis) * wallAxis;
    const double d = rho.norm();
    const Eigen::Vector3d radial = d > 0.0 ? Eigen::Vector3d(rho / d) : Eigen::Vector3d(-normal);
    n = -radial;
    const double sideDepth = d + scopeRadius - wallRadius;
    side = 1.0;
    toApex = 0.0;
    if (!endCap) {
        return sideDepth;
    }
    // The cone from the dome ring (radius a) to the apex (height b): the
    // node's signed distance past it, in the plane of the axis and the node.
    const Eigen::Vector3d rel = x - capCentre;
    const double h = rel.dot(capAxis);
    Eigen::Vector3d across = rel - h * capAxis;
    const double rhoCap = across.norm();
    const Eigen::Vector3d e = rhoCap > 0.0 ? Eigen::Vector3d(across / rhoCap) : radial;
    const double a = wallRadius;
    const double b = capHeight;
    const double slant = std::hypot(a, b);
    const double capDepth = scopeRadius + ((rhoCap - a) * b + h * a) / slant;
    const Eigen::Vector3d capNormal = -(b * e + a * capAxis) / slant;
    toApex = a > 0.0 ? std::clamp(1.0 - rhoCap / a, 0.0, 1.0) : 1.0;
    // Smooth maximum over a width of the scope's radius: the depth is
    // (1 - s) side + s cap + k s (1 - s), whose gradient is
    // (1 - s) grad side + s grad cap.
    const double k = std::max(scopeRadius, kMinCapHeight);
    const double s = std::clamp(0.5 + 0.5 * (capDepth - sideDepth) / k, 0.0, 1.0);
    side = 1.0 - s;
    const Eigen::Vector3d blended = (1.0 - s) * n + s * capNormal;
    n = blended.normalized();
    return (1.0 - s) * sideDepth + s * capDepth + k * s * (1.0 - s);
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
