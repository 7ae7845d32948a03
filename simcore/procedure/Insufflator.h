#pragma once
/// \file
/// The insufflator: while the air button is held the colon's luminal
/// pressure rises at a set rate, and suction lowers it at the same rate, up
/// to a ceiling the insufflator never exceeds.

#include "simcore/params/Parameter.h"

#include <span>

namespace colonosim::procedure {

struct InsufflatorParameters {
    using Spec = params::ParameterSpec;
    static constexpr Spec pressureRateSpec{
        "pressureRate",
        "Pa/s",
        266.6,
        0.0,
        2000.0,
        "rate at which the luminal pressure rises while air is pressed, and falls while suction is (2 "
        "mmHg/s)",
        "assumption: the 9-57 mmHg of luminal pressure measured during colonoscopy with the tip free "
        "(reference/physical-parameters.md, air-pressure colon injury study) is reached over seconds "
        "to tens of seconds of air, not in one press"};
    static constexpr Spec maxPressureSpec{
        "maxPressure",
        "Pa",
        8000.0,
        0.0,
        10800.0,
        "luminal pressure the insufflator never exceeds (60 mmHg)",
        "reference/physical-parameters.md: up to 57 mmHg measured with the tip free during colonoscopy, "
        "below the cadaver cecum's 81 mmHg rupture pressure, where the range ends (as the environment's "
        "insufflationPressure does)"};

    double pressureRate = pressureRateSpec.defaultValue;
    double maxPressure = maxPressureSpec.defaultValue;

    [[nodiscard]] static std::span<const params::Field<InsufflatorParameters>> fields();
    /// Throws ParameterError naming the field, the value and the range.
    void validate() const;
};

}  // namespace colonosim::procedure
