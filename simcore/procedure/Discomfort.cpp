#include "simcore/procedure/Discomfort.h"

#include <algorithm>
#include <cmath>

namespace colonosim::procedure {

namespace {
double ramp(double value, double onset, double full)
{
    if (!(full > onset)) {
        return value >= onset ? 10.0 : 0.0;
    }
    return 10.0 * std::clamp((value - onset) / (full - onset), 0.0, 1.0);
}
}  // namespace

void DiscomfortParameters::validate() const
{
    params::require("discomfort", pressureOnsetSpec, painOnsetPressure);
    params::require("discomfort", pressureMaxSpec, severePainPressure);
    params::require("discomfort", strainOnsetSpec, painOnsetStrain);
    params::require("discomfort", stressOnsetSpec, painOnsetStress);
    params::require("discomfort", strengthSpec, wallTensileStrength);
    params::require("discomfort", ruptureSpec, rupturePressure);
    params::require("discomfort", lagSpec, painLag);
    if (!(severePainPressure > painOnsetPressure) || !(mesenteryFailureStrain > painOnsetStrain) ||
        !(wallTensileStrength > painOnsetStress)) {
        throw params::ParameterError("discomfort: every pain onset must lie below its severe level");
    }
}

DiscomfortModel::DiscomfortModel(const DiscomfortParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
}

double DiscomfortModel::instantaneous(const DiscomfortInput& input) const
{
    const DiscomfortParameters& p = m_parameters;
    return std::max({ramp(input.luminalPressure, p.painOnsetPressure, p.severePainPressure),
                     ramp(input.mesenteryStrain, p.painOnsetStrain, p.mesenteryFailureStrain),
                     ramp(input.wallStress, p.painOnsetStress, p.wallTensileStrength)});
}

double DiscomfortModel::update(const DiscomfortInput& input, double dt)
{
    const double target = instantaneous(input);
    const double blend = m_parameters.painLag > 0.0 ? 1.0 - std::exp(-dt / m_parameters.painLag) : 1.0;
    m_score += blend * (target - m_score);
    return m_score;
}

bool DiscomfortModel::perforates(const DiscomfortInput& input) const
{
    return input.wallStress >= m_parameters.wallTensileStrength ||
           input.luminalPressure >= m_parameters.rupturePressure;
}

int comfortScale(double score)
{
    if (score < 1.0) {
        return 1;
    }
    if (score < 3.0) {
        return 2;
    }
    if (score < 5.0) {
        return 3;
    }
    if (score < 7.5) {
        return 4;
    }
    return 5;
}

}  // namespace colonosim::procedure
