#include "simcore/scope/ScopeParameters.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace colonosim::scope {

namespace {
using S = ScopeParameters;
constexpr std::array<Field<S>, 13> kScopeFields{{
    {&S::workingLengthSpec, &S::workingLength},
    {&S::outerDiameterSpec, &S::outerDiameter},
    {&S::flexuralRigiditySpec, &S::flexuralRigidity},
    {&S::torsionalRigiditySpec, &S::torsionalRigidity},
    {&S::linearDensitySpec, &S::linearMassDensity},
    {&S::numNodesSpec, &S::numNodes},
    {&S::bendingSectionSpec, &S::bendingSectionLength},
    {&S::maxUpDownSpec, &S::maxUpDownAngulation},
    {&S::maxLeftRightSpec, &S::maxLeftRightAngulation},
    {&S::iterationsSpec, &S::solverIterations},
    {&S::relaxationSpec, &S::solverRelaxation},
    {&S::jointDampingSpec, &S::jointDampingRatio},
    {&S::maxNodeStepSpec, &S::maxNodeStep},
}};
}  // namespace

std::span<const Field<ScopeParameters>> ScopeParameters::fields()
{
    return kScopeFields;
}

void ScopeParameters::validate() const
{
    params::validateFields<ScopeParameters>("scope", kScopeFields, *this);
    for (const auto& [spec, value] :
         {std::pair{&numNodesSpec, numNodes}, {&iterationsSpec, solverIterations}}) {
        if (value != std::floor(value)) {
            throw params::ParameterError("scope." + std::string(spec->name) + " = " + std::to_string(value) +
                                         " must be a whole number in [" + std::to_string(spec->minValue) +
                                         ", " + std::to_string(spec->maxValue) + "]");
        }
    }
}

}  // namespace colonosim::scope
