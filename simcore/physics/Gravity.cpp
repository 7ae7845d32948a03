#include "simcore/physics/Gravity.h"

#include "simcore/params/Parameter.h"

#include <string>

namespace colonosim::physics {

Eigen::Vector3d downDirection(PatientPosition position)
{
    switch (position) {
    case PatientPosition::Supine: return Eigen::Vector3d::UnitY();
    case PatientPosition::Prone: return -Eigen::Vector3d::UnitY();
    case PatientPosition::LeftLateral: return Eigen::Vector3d::UnitX();
    case PatientPosition::RightLateral: return -Eigen::Vector3d::UnitX();
    }
    return Eigen::Vector3d::UnitY();
}

std::string_view patientPositionName(PatientPosition position)
{
    switch (position) {
    case PatientPosition::Supine: return "supine";
    case PatientPosition::Prone: return "prone";
    case PatientPosition::LeftLateral: return "left_lateral";
    case PatientPosition::RightLateral: return "right_lateral";
    }
    return "supine";
}

PatientPosition parsePatientPosition(std::string_view text)
{
    for (const PatientPosition p : {PatientPosition::Supine, PatientPosition::Prone,
                                    PatientPosition::LeftLateral, PatientPosition::RightLateral}) {
        if (patientPositionName(p) == text) {
            return p;
        }
    }
    throw params::ParameterError("environment.patientPosition = \"" + std::string(text) +
                                 "\" is not one of supine, prone, left_lateral, right_lateral");
}

void Gravity::addForce(const Positions& /*x*/, Forces& f) const
{
    for (const int i : m_awake.entries()) {
        f.col(i) += m_mass[i] * m_g;
    }
}

double Gravity::potentialEnergy(const Positions& x) const
{
    double energy = 0.0;
    for (Eigen::Index i = 0; i < m_mass.size(); ++i) {
        energy -= m_mass[i] * m_g.dot(x.col(i));
    }
    return energy;
}

}  // namespace colonosim::physics
