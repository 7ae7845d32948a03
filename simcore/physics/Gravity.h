#pragma once
/// \file
/// Gravity, f_i = m_i g, with g set by the patient's position on the table.
/// In patient LPS coordinates (x left, y posterior, z superior) the downward
/// direction is +y supine, -y prone, +x left lateral decubitus (the usual
/// position for colonoscopy) and -x right lateral.

#include "simcore/physics/AwakeEntries.h"
#include "simcore/physics/ForceTerm.h"

#include <string_view>

namespace colonosim::physics {

enum class PatientPosition { Supine, Prone, LeftLateral, RightLateral };

/// Unit vector pointing down, in patient coordinates.
[[nodiscard]] Eigen::Vector3d downDirection(PatientPosition position);
[[nodiscard]] std::string_view patientPositionName(PatientPosition position);
/// Parses "supine", "prone", "left_lateral", "right_lateral"; throws
/// ParameterError naming the field, the value and the allowed values.
[[nodiscard]] PatientPosition parsePatientPosition(std::string_view text);

class Gravity final : public ForceTerm {
public:
    /// `masses` (kg) is copied; g in m/s^2.
    Gravity(const Eigen::VectorXd& masses, const Eigen::Vector3d& acceleration)
        : m_mass(masses), m_g(acceleration)
    {
        m_awake.rebuildPerNode(static_cast<int>(m_mass.size()), {});
    }

    [[nodiscard]] std::string_view name() const override { return "gravity"; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions&, const Velocities&, Forces&) const override {}
    void addStiffnessProduct(const Positions&, const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&) const override {}
    void addDampingProduct(const Positions&, const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&) const override {}
    void addStiffnessBound(const Positions&, Eigen::VectorXd&, Eigen::VectorXd&) const override {}
    [[nodiscard]] double potentialEnergy(const Positions& x) const override;
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
    Eigen::Vector3d m_g;
    AwakeEntries m_awake;  ///< awake nodes (the force sums)
};

}  // namespace colonosim::physics
