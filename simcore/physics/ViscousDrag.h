#pragma once
/// \file
/// Drag of the surrounding abdominal contents on the colon wall, a
/// mass-proportional (Rayleigh alpha) damping: f_i = -alpha m_i v_i,
/// D_ii = -alpha m_i I. Stiffness-proportional spring damping (c = beta k)
/// leaves the colon's slow pendulum modes on the mesentery almost undamped;
/// this declared term damps them, as the fluid-filled viscera around the
/// colon do. It is a declared parameter (TissueParameters::surroundingDampingRate),
/// never a hidden default.

#include "simcore/physics/AwakeEntries.h"
#include "simcore/physics/ForceTerm.h"

namespace colonosim::physics {

class ViscousDrag final : public ForceTerm {
public:
    /// `masses` in kg (copied); alpha in 1/s.
    ViscousDrag(const Eigen::VectorXd& masses, double rate) : m_mass(masses), m_rate(rate)
    {
        m_awake.rebuildPerNode(static_cast<int>(m_mass.size()), {});
    }

    [[nodiscard]] std::string_view name() const override { return "surrounding_drag"; }
    void addForce(const Positions&, Forces&) const override {}
    void addDampingForce(const Positions&, const Velocities& v, Forces& f) const override
    {
        for (const int i : m_awake.entries()) {
            f.col(i) -= (m_rate * m_mass[i]) * v.col(i);
        }
    }
    void addStiffnessProduct(const Positions&, const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&) const override {}
    void addDampingProduct(const Positions&, const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df) const override
    {
        for (Eigen::Index i = 0; i < m_mass.size(); ++i) {
            df.col(i) -= (m_rate * m_mass[i]) * dv.col(i);
        }
    }
    void addStiffnessBound(const Positions&, Eigen::VectorXd&, Eigen::VectorXd& cRow) const override
    {
        cRow += m_rate * m_mass;
    }
    [[nodiscard]] double potentialEnergy(const Positions&) const override { return 0.0; }
    void onMassesChanged(const Eigen::VectorXd& masses) override
    {
        m_mass = masses;
        m_awake.rebuildPerNode(static_cast<int>(m_mass.size()));
    }
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override
    {
        m_awake.rebuildPerNode(static_cast<int>(m_mass.size()), awake);
    }

private:
    Eigen::VectorXd m_mass;
    double m_rate;
    AwakeEntries m_awake;  ///< awake nodes (the drag sums)
};

}  // namespace colonosim::physics
