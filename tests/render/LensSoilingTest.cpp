// The lens soiling model against its closed-form solution.

#include "simcore/render/LensSoiling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using colonosim::render::LensSoiling;
using colonosim::render::RenderParameters;

TEST(LensSoiling, ContactSoilsAndWashClearsAsTheClosedFormSays)
{
    const RenderParameters p;
    LensSoiling lens(p);
    // 0.8 s in contact at 1 kHz, then 0.5 s away from the wall, then a 0.4 s wash.
    for (int k = 0; k < 800; ++k) {
        lens.update(1e-3, 0.0, false);
    }
    const double soiled = 1.0 - std::exp(-p.soilingRate * 0.8);
    // Each step is integrated exactly: only rounding separates the two.
    EXPECT_NEAR(lens.amount(), soiled, 1e-12);
    for (int k = 0; k < 500; ++k) {
        lens.update(1e-3, 0.02, false);
    }
    EXPECT_NEAR(lens.amount(), soiled, 1e-12);  // stays until washed
    for (int k = 0; k < 400; ++k) {
        lens.update(1e-3, 0.02, true);
    }
    EXPECT_NEAR(lens.amount(), soiled * std::exp(-p.washRate * 0.4), 1e-12);
}

TEST(LensSoiling, RefusesInvalidRates)
{
    RenderParameters p;
    p.washRate = -1.0;
    EXPECT_THROW(LensSoiling{p}, colonosim::params::ParameterError);
}

}  // namespace
