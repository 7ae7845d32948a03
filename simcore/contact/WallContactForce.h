#pragma once
/// \file
/// The wall's side of scope-wall contact during the tissue substeps.
///
/// Contacts are found once per loop step (ScopeWallContact). Holding their
/// normal forces constant over the substeps would be an explicit coupling
/// with k_c dt^2 / m far above 4 for a 0.2 g wall node at 1 kHz: unstable.
/// Instead each contact is kept as a force term over the substeps, with the
/// scope's axis point p (the scope is solved once per loop step) fixed and
/// the wall point moving with its triangle, w(x) = sum_m b_m x_m:
///   depth(x) = r - (p - w(x)) . n,  n the unit normal into the lumen,
///   f_m = -b_m max(0, k_c depth + c_n (v_w . n)) n    on vertex m,
///   K_ml = -k_c b_m b_l n n^T,  D_ml = -c_n b_m b_l n n^T   while in contact.
/// The friction force of the loop step, bounded by mu f_n, is applied as a
/// constant load (it stiffens nothing). For the stable-step plan the term
/// reserves k_c and c_n at every wall node (a contact may appear anywhere),
/// so the plan made once stays valid as contacts come and go.

#include "simcore/contact/ScopeWallContact.h"
#include "simcore/physics/ForceTerm.h"

#include <array>
#include <vector>

namespace colonosim::contact {

/// How the wall sees one contact's scope point during the substeps.
struct WallContactPoint {
    Eigen::Vector3d axisPoint = Eigen::Vector3d::Zero();  ///< scope axis point, m
    double stiffness = 0.0;                               ///< N/m, in (0, k_c]: k_c for a rigid scope
    double depthOffset = 0.0;    ///< m added to the depth (the scope's own deflection under its load)
    double frictionScale = 1.0;  ///< the contact's friction force is scaled by this, 1
};

class WallContactForce final : public physics::ForceTerm {
public:
    WallContactForce(const geometry::TriangleMesh& wallMesh, const ContactParameters& parameters,
                     int numWallNodes);

    /// Takes this loop step's contacts; `scopeAxisPoints` are the scope axis
    /// points of the contacts (one per contact), `radius` the scope's, m.
    /// The scope is rigid here: stiffness k_c, no offset (for tests and tools;
    /// allocates, so the procedure loop uses the overload below).
    void setContacts(const std::vector<ScopeContact>& contacts,
                     const std::vector<Eigen::Vector3d>& scopeAxisPoints, double radius);
    /// The scope is compliant: each contact with its own stiffness and depth
    /// offset (see procedure/ContactCoupling.h). Stiffnesses above k_c are
    /// clamped to k_c, which the stable-step plan reserves.
    void setContacts(const std::vector<ScopeContact>& contacts, const std::vector<WallContactPoint>& points,
                     double radius);
    [[nodiscard]] int numContacts() const { return static_cast<int>(m_contacts.size()); }

    [[nodiscard]] std::string_view name() const override { return "scope_contact"; }
    void addForce(const physics::Positions& x, physics::Forces& f) const override;
    void addDampingForce(const physics::Positions& x, const physics::Velocities& v,
                         physics::Forces& f) const override;
    void addStiffnessProduct(const physics::Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const physics::Positions& x, const Eigen::Matrix3Xd& dv,
                           Eigen::Matrix3Xd& df) const override;
    void addStiffnessBound(const physics::Positions& x, Eigen::VectorXd& kRow,
                           Eigen::VectorXd& cRow) const override;
    [[nodiscard]] double potentialEnergy(const physics::Positions& x) const override;

private:
    struct Active {
        std::array<int, 3> vertices;
        Eigen::Vector3d barycentric;
        Eigen::Vector3d normal;     ///< into the lumen
        Eigen::Vector3d axisPoint;  ///< scope axis, m
        Eigen::Vector3d friction;   ///< on the wall, N
        double stiffness;           ///< N/m
        double depthOffset;         ///< m
    };
    [[nodiscard]] double depth(const Active& c, const physics::Positions& x) const;

    const geometry::TriangleMesh& m_mesh;
    ContactParameters m_parameters;
    int m_numWallNodes;
    double m_radius = 0.0;
    std::vector<Active> m_contacts;
};

}  // namespace colonosim::contact
