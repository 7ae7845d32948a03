#include "simcore/render/RenderParameters.h"

#include <array>
#include <cmath>
#include <string>

namespace colonosim::render {

namespace {
using R = RenderParameters;
using params::Field;
constexpr std::array<Field<R>, 19> kRenderFields{{
    {&R::fieldOfViewSpec, &R::fieldOfView},
    {&R::lightIntensitySpec, &R::lightIntensity},
    {&R::autoLightDistanceSpec, &R::autoLightDistance},
    {&R::autoLightConeSpec, &R::autoLightCone},
    {&R::spotExponentSpec, &R::spotExponent},
    {&R::specularSpec, &R::specular},
    {&R::bumpDepthSpec, &R::bumpDepth},
    {&R::fluidAttenuationSpec, &R::fluidAttenuation},
    {&R::redOutDistanceSpec, &R::redOutDistance},
    {&R::contactDistanceSpec, &R::contactDistance},
    {&R::nearDistanceSpec, &R::nearDistance},
    {&R::farDistanceSpec, &R::farDistance},
    {&R::levelOfDetailErrorSpec, &R::levelOfDetailError},
    {&R::workingDistanceSpec, &R::workingDistance},
    {&R::maxIncidenceSpec, &R::maxIncidence},
    {&R::coverageIntervalSpec, &R::coverageInterval},
    {&R::coverageResolutionSpec, &R::coverageResolution},
    {&R::soilingRateSpec, &R::soilingRate},
    {&R::washRateSpec, &R::washRate},
}};
}  // namespace

std::span<const Field<RenderParameters>> RenderParameters::fields()
{
    return kRenderFields;
}

void RenderParameters::validate() const
{
    params::validateFields<RenderParameters>("render", kRenderFields, *this);
    if (contactDistance >= redOutDistance) {
        throw params::ParameterError(
            "render.contactDistance = " + std::to_string(contactDistance) +
            " m must be below render.redOutDistance = " + std::to_string(redOutDistance) + " m");
    }
    if (nearDistance >= farDistance) {
        throw params::ParameterError("render.nearDistance = " + std::to_string(nearDistance) +
                                     " m must be below render.farDistance = " + std::to_string(farDistance) +
                                     " m");
    }
    if (coverageResolution != std::floor(coverageResolution)) {
        throw params::ParameterError("render.coverageResolution = " + std::to_string(coverageResolution) +
                                     " must be a whole number in [32, 1024]");
    }
}

}  // namespace colonosim::render
