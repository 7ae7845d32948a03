#include "simcore/physics/TissueParameters.h"

#include <array>

namespace colonosim::physics {

namespace {
using T = TissueParameters;
constexpr std::array<Field<T>, 16> kTissueFields{{
    {&T::youngModulusSpec, &T::wallYoungModulus},
    {&T::thicknessSpec, &T::wallThickness},
    {&T::densitySpec, &T::wallDensity},
    {&T::shearRatioSpec, &T::shearStiffnessRatio},
    {&T::bendingRatioSpec, &T::bendingStiffnessRatio},
    {&T::haustralAxialSpec, &T::haustralAxialRatio},
    {&T::dampingTimeSpec, &T::dampingTime},
    {&T::transverseDampingSpec, &T::transverseDampingRatio},
    {&T::mesenteryModulusSpec, &T::mesenteryModulus},
    {&T::mesenteryThicknessSpec, &T::mesenteryThickness},
    {&T::stiffeningStrainSpec, &T::mesenteryStiffeningStrain},
    {&T::maxStrainSpec, &T::mesenteryMaxStrain},
    {&T::retroperitonealSpec, &T::retroperitonealStiffness},
    {&T::adhesionSpec, &T::adhesionStiffness},
    {&T::surroundingDampingSpec, &T::surroundingDampingRate},
    {&T::selfContactSpec, &T::selfContactStiffness},
}};
using E = EnvironmentParameters;
constexpr std::array<Field<E>, 2> kEnvironmentFields{{
    {&E::gravitySpec, &E::gravity},
    {&E::pressureSpec, &E::insufflationPressure},
}};
}  // namespace

std::span<const Field<TissueParameters>> TissueParameters::fields()
{
    return kTissueFields;
}

void TissueParameters::validate() const
{
    params::validateFields<TissueParameters>("tissue", kTissueFields, *this);
    if (mesenteryMaxStrain < mesenteryStiffeningStrain) {
        throw params::ParameterError(
            "tissue.mesenteryMaxStrain = " + std::to_string(mesenteryMaxStrain) +
            " must be >= tissue.mesenteryStiffeningStrain = " + std::to_string(mesenteryStiffeningStrain));
    }
}

std::span<const Field<EnvironmentParameters>> EnvironmentParameters::fields()
{
    return kEnvironmentFields;
}

void EnvironmentParameters::validate() const
{
    params::validateFields<EnvironmentParameters>("environment", kEnvironmentFields, *this);
}

}  // namespace colonosim::physics
