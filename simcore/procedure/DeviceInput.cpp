#include "simcore/procedure/DeviceInput.h"

#include <cmath>

namespace colonosim::procedure {

std::string validateInput(const InputSample& sample)
{
    const struct {
        const params::ParameterSpec* spec;
        double value;
        const char* field;
    } checks[] = {
        {&InputSample::insertionSpec, sample.insertion, "insertion"},
        {&InputSample::rotationSpec, sample.rotation, "rotation"},
        {&InputSample::dialSpec, sample.dialUpDown, "dialUpDown"},
        {&InputSample::dialSpec, sample.dialLeftRight, "dialLeftRight"},
    };
    for (const auto& check : checks) {
        if (!check.spec->accepts(check.value)) {
            params::ParameterSpec named = *check.spec;
            named.name = check.field;
            return params::describeRejection("input", named, check.value);
        }
    }
    if ((sample.buttons & ~(kAir | kWater | kSuction | kMarkLesion)) != 0) {
        return "input.buttons = " + std::to_string(sample.buttons) +
               " is outside the allowed range [0, 15] (bits: air 1, water 2, suction 4, mark lesion 8)";
    }
    return {};
}

InputSample quantizeInput(const InputSample& sample)
{
    const auto round = [](double value, double step) { return std::nearbyint(value / step) * step; };
    InputSample q = sample;
    q.insertion = round(sample.insertion, InputResolution::insertionSpec.defaultValue);
    q.rotation = round(sample.rotation, InputResolution::angleSpec.defaultValue);
    q.dialUpDown = round(sample.dialUpDown, InputResolution::angleSpec.defaultValue);
    q.dialLeftRight = round(sample.dialLeftRight, InputResolution::angleSpec.defaultValue);
    return q;
}

}  // namespace colonosim::procedure
