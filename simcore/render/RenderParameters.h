#pragma once
/// \file
/// Declared parameters of the endoscope view, the lens effects and the
/// coverage measurement (SI; angles in radians).

#include "simcore/params/Parameter.h"

#include <span>

namespace colonosim::render {

struct RenderParameters {
    using Spec = params::ParameterSpec;
    static constexpr Spec fieldOfViewSpec{"fieldOfView",
                                          "rad",
                                          2.7925,
                                          1.7453,
                                          2.9671,
                                          "full angle of the lens's image circle (160 deg; 100-170 deg)",
                                          "colonoscope specifications: 140 deg (Olympus CF-Q160) to 170 deg "
                                          "(Olympus CF-HQ190)"};
    static constexpr Spec lightIntensitySpec{
        "lightIntensity",
        "1",
        8.0,
        0.05,
        20.0,
        "exposure: relative irradiance of a wall facing the tip at 1 cm",
        "model choice: a wall at 1-3 cm is well exposed, as on a video scope"};
    static constexpr Spec autoLightDistanceSpec{
        "autoLightDistance",
        "m",
        0.025,
        0.0,
        0.05,
        "automatic light control: nearer than this, the light is dimmed as (d / this)^2 (0: off)",
        "video processors' automatic brightness keeps a near wall from glaring; model choice of the "
        "distance"};
    static constexpr Spec autoLightConeSpec{
        "autoLightCone",
        "rad",
        0.5236,
        0.0175,
        1.5708,
        "automatic light control: half-angle about the view axis in which the nearest wall is measured",
        "model choice: the middle of the image (30 deg) sets the exposure, as centre-weighted metering"};
    static constexpr Spec spotExponentSpec{
        "spotExponent",
        "1",
        1.5,
        0.0,
        20.0,
        "cone of the light guides: irradiance times cos(angle off axis)^k",
        "model choice (the two light guides spread over the field of view)"};
    static constexpr Spec specularSpec{
        "specular",
        "1",
        0.6,
        0.0,
        3.0,
        "strength of the wet mucosa's specular highlight relative to diffuse",
        "model choice after de Visser et al. 2010, fig. 6 (submucosal reflection)"};
    static constexpr Spec bumpDepthSpec{
        "bumpDepth",
        "m",
        2e-4,
        0.0,
        1e-3,
        "relief of the fine mucosal texture used for normal perturbation",
        "innominate grooves and areae of the colonic mucosa, about 0.1-0.3 mm"};
    static constexpr Spec fluidAttenuationSpec{
        "fluidAttenuation",
        "1/m",
        80.0,
        5.0,
        2000.0,
        "residual fluid: attenuation of light in the liquid (green; red 0.6 and blue 1.8 times this), "
        "exp(-mu x) over the path x in and out",
        "model choice: bile-stained residual fluid shows the mucosa dimly through 5 mm (45% of the green "
        "light comes back, in and out) and hides it under 2 cm (4%) or in a grazing view, as on endoscopic "
        "images of poorly prepared colons"};
    static constexpr Spec redOutDistanceSpec{
        "redOutDistance",
        "m",
        4e-3,
        1e-3,
        0.02,
        "lens-to-wall distance below which the view starts to turn red",
        "model choice: red-out appears within a few millimetres of contact"};
    static constexpr Spec contactDistanceSpec{"contactDistance",
                                              "m",
                                              1.5e-3,
                                              0.0,
                                              0.01,
                                              "lens-to-wall distance at which the view is fully red",
                                              "model choice: the lens sits recessed about 1 mm in the tip"};
    static constexpr Spec nearDistanceSpec{"nearDistance",
                                           "m",
                                           2e-4,
                                           1e-5,
                                           0.01,
                                           "closest depth drawn",
                                           "model choice (below the contact distance)"};
    static constexpr Spec farDistanceSpec{"farDistance",
                                          "m",
                                          0.3,
                                          0.05,
                                          5.0,
                                          "farthest depth drawn",
                                          "inverse-square light at the default exposure: wall beyond 30 cm "
                                          "is below 2% of full scale"};
    static constexpr Spec levelOfDetailErrorSpec{
        "levelOfDetailError",
        "px",
        1.0,
        0.0,
        8.0,
        "largest geometric error of a coarser level of the wall mesh, seen on the screen (0: full "
        "detail everywhere)",
        "geometrical mipmapping (de Boer 2000): a level is used while its error projects under a pixel"};
    static constexpr Spec workingDistanceSpec{
        "workingDistance",
        "m",
        0.05,
        0.005,
        0.3,
        "coverage: wall farther than this from the lens counts as unseen",
        "model choice: mucosa is inspected within about 5 cm of the tip"};
    static constexpr Spec maxIncidenceSpec{
        "maxIncidence",
        "rad",
        1.3090,
        0.1745,
        1.5533,
        "coverage: largest angle between the view ray and the wall normal "
        "(75 deg) at which the wall counts as seen",
        "model choice: grazing views (behind folds) do not show the mucosa"};
    static constexpr Spec coverageIntervalSpec{"coverageInterval",
                                               "s",
                                               0.1,
                                               0.005,
                                               2.0,
                                               "simulated time between coverage updates (10 Hz)",
                                               "model choice: a glance of 0.1 s is the shortest that counts"};
    static constexpr Spec coverageResolutionSpec{"coverageResolution",
                                                 "1",
                                                 192,
                                                 32,
                                                 1024,
                                                 "side of the square ID buffer of the coverage pass, pixels",
                                                 "model choice: a 1 cm^2 patch at 5 cm still covers pixels"};

    static constexpr Spec soilingRateSpec{"soilingRate",
                                          "1/s",
                                          0.5,
                                          0.0,
                                          10.0,
                                          "lens soiling gained per second while the lens touches the mucosa",
                                          "model choice: a second of wall contact smears half the lens"};
    static constexpr Spec washRateSpec{
        "washRate",
        "1/s",
        3.0,
        0.1,
        50.0,
        "decay rate of lens soiling while the water jet (lens wash) runs",
        "model choice: a one-second lens wash clears about 95% of the soiling"};

    double fieldOfView = fieldOfViewSpec.defaultValue;
    double lightIntensity = lightIntensitySpec.defaultValue;
    double autoLightDistance = autoLightDistanceSpec.defaultValue;
    double autoLightCone = autoLightConeSpec.defaultValue;
    double spotExponent = spotExponentSpec.defaultValue;
    double specular = specularSpec.defaultValue;
    double bumpDepth = bumpDepthSpec.defaultValue;
    double fluidAttenuation = fluidAttenuationSpec.defaultValue;
    double redOutDistance = redOutDistanceSpec.defaultValue;
    double contactDistance = contactDistanceSpec.defaultValue;
    double nearDistance = nearDistanceSpec.defaultValue;
    double farDistance = farDistanceSpec.defaultValue;
    double levelOfDetailError = levelOfDetailErrorSpec.defaultValue;
    double workingDistance = workingDistanceSpec.defaultValue;
    double maxIncidence = maxIncidenceSpec.defaultValue;
    double coverageInterval = coverageIntervalSpec.defaultValue;
    double coverageResolution = coverageResolutionSpec.defaultValue;
    double soilingRate = soilingRateSpec.defaultValue;
    double washRate = washRateSpec.defaultValue;

    [[nodiscard]] static std::span<const params::Field<RenderParameters>> fields();
    /// Throws ParameterError naming the field, value and range; also when
    /// contactDistance >= redOutDistance or nearDistance >= farDistance.
    void validate() const;
};

}  // namespace colonosim::render
