#pragma once
/// \file
/// Scope-wall contact against the lumen (LumenTube.h): for every scope node,
/// its signed depth into the wall, the contact normal, the wall point's nodes
/// and weights, and the slip velocity for friction.
///
/// A scope node p of radius r at its station (searched around its own
/// station of the last step; see compute()) lies at distance d
/// from the lumen axis, where the wall is at radius R along the same radial
/// direction e:
///   depth = d + r - R    (> 0: pressed into the wall),  normal = -e
/// (onto the scope, towards the axis). Beyond the dome ring the lumen is
/// closed by the cone from the dome ring (radius a) to the apex (height b
/// past the ring's plane), as the physics mesh closes it: a node at height h
/// and distance rho from the axis lies ((rho - a) b + h a) / sqrt(a^2 + b^2)
/// past it, normal -(b e + a x) / sqrt(a^2 + b^2) (x the ring's axis), on the
/// apex and the dome ring's nodes. The side wall and the cone meet at the
/// dome ring at 70-80 degrees: the two depths are joined by a smooth maximum
/// rounded over the scope's radius, so that the normal of a node sliding
/// round the corner turns with it instead of jumping between the two walls
/// (a jump past 45 degrees drops the load it carries; see ContactCoupling).
/// Every node gets an entry, in contact or not, so the coupling releases a
/// load as soon as the wall has moved away (depth < 0).
///
/// Friction is Coulomb with the regularised stick of ScopeWallContact.h,
/// f_t = -mu f_n v_t / max(|v_t|, v_s), v_t the tangential part of the scope
/// node's velocity relative to the wall point; it is applied with the normal
/// force the coupling settles on (procedure/ContactCoupling.h).

#include "simcore/contact/ContactParameters.h"
#include "simcore/contact/LumenTube.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::contact {

struct LumenNodeContact {
    double depth = 0.0;                                ///< signed, m: > 0 pressed into the wall
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit, onto the scope, into the lumen
    Eigen::Vector3d slip = Eigen::Vector3d::Zero();    ///< tangential velocity, scope minus wall, m/s
    double lever = 0.0;  ///< distance from the lumen axis (radial) or the dome ring's radius (beyond it), m:
                         ///< the normal turns by dx / lever
    std::array<int, 4> wallNodes{};   ///< the wall point's nodes
    std::array<double, 4> weights{};  ///< their weights (sum 1)
    LumenStation station;
    bool endCap = false;  ///< beyond the dome ring: the side wall and the closed end's cone
    // The local wall as a cylinder (axis point, unit axis, wall radius) and,
    // beyond the dome ring, the end's cone (the dome ring's centre and unit
    // axis, and the apex's height past it; its base radius is wallRadius):
    // the contact re-measured at nearby points without a new search.
    Eigen::Vector3d wallCentre = Eigen::Vector3d::Zero();
    Eigen::Vector3d wallAxis = Eigen::Vector3d::UnitZ();
    double wallRadius = 0.0;  ///< m (cylinder; the cone's base)
    Eigen::Vector3d capCentre = Eigen::Vector3d::Zero();
    Eigen::Vector3d capAxis = Eigen::Vector3d::UnitZ();  ///< out of the lumen, towards the apex
    double capHeight = 0.0;                              ///< m
    double scopeRadius = 0.0;                            ///< m

    /// Signed depth at a point `x` near the node on the local wall, m; `n`
    /// receives the normal (onto the scope, into the lumen).
    [[nodiscard]] double depthAt(const Eigen::Vector3d& x, Eigen::Vector3d& n) const;
    /// The same, with the side wall's share of the blend beyond the dome ring
    /// (1 elsewhere) and the cone's share on its apex (0 at the dome ring, 1
    /// on the axis).
    double depthAt(const Eigen::Vector3d& x, Eigen::Vector3d& n, double& side, double& toApex) const;
};

class LumenContact {
public:
    /// Throws params::ParameterError for invalid parameters or a mesh that
    /// is not a tube of rings.
    LumenContact(const geometry::ColonAnatomy& anatomy, const ContactParameters& parameters);

    /// One entry per scope node (3 x n positions and velocities, base to tip).
    /// `addedAtBase`: nodes that entered at the base since the last call
    /// (negative when nodes left; kNoHistory when the nodes are not the last
    /// call's). With a history each node's station is searched around its own
    /// station of the last call (a node moves a fraction of a millimetre per
    /// step); a new node, or every node without a history, searches around
    /// its base-side neighbour's (the base node around the anus). The
    /// neighbour's station alone loses its way where the colon is pleated on
    /// the shaft and consecutive nodes lie more than the search's four
    /// sections apart. A node whose centre lies outside its station's wall
    /// is searched on, up to 16 sections, for a section whose wall holds it
    /// and that lies towards its base-side neighbour's section (the anus for
    /// the base node): where the colon is folded back on itself the walk,
    /// which moves only while the centre polyline comes closer, is held at
    /// the fold's far leg, and the node would be pushed towards the wrong
    /// part of the colon. A section away from the neighbour is taken only
    /// with contact.pleatSearch 1, and only where the shaft's segment from
    /// the neighbour to the node passes through every ring in between within
    /// the scope's radius of its wall (LumenTube::passesThrough): the colon
    /// pleated on the shaft, its rings packed and tilted so that the walk is
    /// held on a fold of the pleat. A node pushed through its wall into a
    /// neighbouring loop (the segment leaves the lumen) is still pushed back
    /// the way it came. `wallMoved` false: `wall` is the one of the last call
    /// and the tube's rings are not measured again.
    const std::vector<LumenNodeContact>& compute(const Eigen::Matrix3Xd& scope,
                                                 const Eigen::Matrix3Xd& scopeVelocities, double radius,
                                                 const Eigen::Matrix3Xd& wall,
                                                 const Eigen::Matrix3Xd& wallVelocities,
                                                 int addedAtBase = kNoHistory, bool wallMoved = true);
    static constexpr int kNoHistory = -(1 << 30);
    /// With contact.spinFriction: adds to each contact's slip the velocity of
    /// the scope's surface at the wall from the shaft's spin, -r w x n (w the
    /// angular velocity about the shaft's axis at the contact, one column per
    /// contact of the last compute(), rad/s, world; r the scope's radius),
    /// so that friction opposes the surface's slip, not the axis's.
    void addSurfaceSpin(const Eigen::Matrix3Xd& spin);

    [[nodiscard]] const std::vector<LumenNodeContact>& contacts() const { return m_contacts; }
    [[nodiscard]] const LumenTube& tube() const { return m_tube; }
    [[nodiscard]] const ContactParameters& parameters() const { return m_parameters; }

    /// Friction on the scope for normal force `normalForce` at `contact`, N,
    /// with the stick regularised below max(v_s, `minStickVelocity`) m/s.
    [[nodiscard]] Eigen::Vector3d friction(const LumenNodeContact& contact, double normalForce,
                                           double minStickVelocity = 0.0) const;

private:
    ContactParameters m_parameters;
    LumenTube m_tube;
    std::vector<LumenNodeContact> m_contacts;
    std::vector<int> m_previousRing;  ///< each node's section at the last call
};

}  // namespace colonosim::contact
