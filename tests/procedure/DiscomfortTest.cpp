// The discomfort model: scores from the reference's pain thresholds, the
// lag, the 5-point scale, and perforation.

#include "simcore/procedure/Discomfort.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::procedure {
namespace {

constexpr double kMmHg = 133.322;  // Pa

TEST(Discomfort, PressureScoresBetweenTwentyAndSeventyMmHg)
{
    const DiscomfortModel model(DiscomfortParameters{});
    EXPECT_EQ(model.instantaneous({15.0 * kMmHg, 0.0, 0.0}), 0.0);
    EXPECT_NEAR(model.instantaneous({45.0 * kMmHg, 0.0, 0.0}), 5.0, 0.01);
    EXPECT_EQ(model.instantaneous({90.0 * kMmHg, 0.0, 0.0}), 10.0);
}

TEST(Discomfort, TheWorstCauseSetsTheScore)
{
    const DiscomfortModel model(DiscomfortParameters{});
    const double stretch = model.instantaneous({0.0, 0.435, 0.0});  // halfway from 0.1 to 0.77
    EXPECT_NEAR(stretch, 5.0, 0.01);
    EXPECT_NEAR(model.instantaneous({30.0 * kMmHg, 0.435, 0.1e6}), stretch, 1e-12);
    EXPECT_GT(model.instantaneous({0.0, 0.0, 0.6e6}), 5.0);
}

TEST(Discomfort, FeltPainLagsItsCause)
{
    DiscomfortModel model(DiscomfortParameters{});
    const DiscomfortInput loop{0.0, 0.77, 0.0};
    model.update(loop, 1.0);  // one time constant
    EXPECT_NEAR(model.score(), 10.0 * (1.0 - std::exp(-1.0)), 1e-9);
    for (int i = 0; i < 100; ++i) {
        model.update(loop, 0.1);
    }
    EXPECT_NEAR(model.score(), 10.0, 1e-3);
    model.update({}, 2.0);
    EXPECT_NEAR(model.score(), 10.0 * std::exp(-2.0), 1e-3) << "relief follows the same lag";
}

TEST(Discomfort, FivePointScale)
{
    EXPECT_EQ(comfortScale(0.0), 1);
    EXPECT_EQ(comfortScale(2.0), 2);
    EXPECT_EQ(comfortScale(4.0), 3);
    EXPECT_EQ(comfortScale(6.0), 4);
    EXPECT_EQ(comfortScale(9.0), 5);
}

TEST(Discomfort, PerforationAtTensileStrengthOrRupturePressure)
{
    const DiscomfortModel model(DiscomfortParameters{});
    EXPECT_FALSE(model.perforates({60.0 * kMmHg, 0.5, 0.5e6}));
    EXPECT_TRUE(model.perforates({0.0, 0.0, 0.9e6}));
    EXPECT_TRUE(model.perforates({82.0 * kMmHg, 0.0, 0.0}));
}

TEST(Discomfort, InconsistentThresholdsAreRefused)
{
    DiscomfortParameters p;
    p.painOnsetPressure = 9000.0;
    p.severePainPressure = 5000.0;
    EXPECT_THROW(DiscomfortModel{p}, params::ParameterError);
    p = DiscomfortParameters{};
    p.painLag = -1.0;
    EXPECT_THROW(DiscomfortModel{p}, params::ParameterError);
}

}  // namespace
}  // namespace colonosim::procedure
