// CUSUM and LC-CUSUM against a worked example computed by hand from the
// published formulas (LearningCurve.h) with p0 = 5%, p1 = 15%, alpha = 0.05,
// beta = 0.20:
//   P = ln(0.15/0.05) = ln 3 = 1.098612
//   Q = ln(0.95/0.85) = 0.111226
//   s = Q/(P+Q) = 0.111226/1.209838 = 0.091934
//   h1 = ln(0.80/0.05)/(P+Q) = 2.772589/1.209838 = 2.291703
//   h0 = -ln(0.95/0.20)/(P+Q) = -1.558145/1.209838 = -1.287895
//   LC-CUSUM: success +Q = +0.111226, failure ln(p0/p1) = -P = -1.098612, h = ln 16 = 2.772589.
// Outcomes F S S F S: CUSUM 0.908066, 0.816131, 0.724197, 1.632263, 1.540328.
// Tolerance 1e-6: the hand values are rounded to 6 decimals.
#include "scoring/LearningCurve.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim::scoring;

TEST(LearningCurve, ParametersOfTheWorkedExample)
{
    const CusumParameters p;
    EXPECT_NEAR(p.s(), 0.091934, 1e-6);
    EXPECT_NEAR(p.upperLimit(), 2.291703, 1e-6);
    EXPECT_NEAR(p.lowerLimit(), -1.287895, 1e-6);
    EXPECT_NEAR(p.lcLimit(), 2.772589, 1e-6);
}

TEST(LearningCurve, CusumOfTheWorkedExample)
{
    const LearningCurve c = learningCurve({true, false, false, true, false}, {});
    const std::vector<double> hand = {0.908066, 0.816131, 0.724197, 1.632263, 1.540328};
    ASSERT_EQ(c.cusum.size(), hand.size());
    for (size_t n = 0; n < hand.size(); ++n) {
        EXPECT_NEAR(c.cusum[n], hand[n], 1e-6) << n;
    }
    // LC-CUSUM: F -> max(0, -1.098612) = 0; S -> 0.111226; S -> 0.222451; F -> 0; S -> 0.111226.
    const std::vector<double> lc = {0.0, 0.111226, 0.222451, 0.0, 0.111226};
    for (size_t n = 0; n < lc.size(); ++n) {
        EXPECT_NEAR(c.lcCusum[n], lc[n], 1e-6) << n;
    }
    EXPECT_EQ(c.competentAt, 0);
    EXPECT_EQ(c.unacceptableAt, 0);
}

TEST(LearningCurve, SignalsCompetenceAndUnacceptableRates)
{
    // One failure then successes: LC-CUSUM needs ceil(2.772589 / 0.111226) = 25 successes -> procedure 26.
    std::vector<bool> outcomes(26, false);
    outcomes[0] = true;
    EXPECT_EQ(learningCurve(outcomes, {}).competentAt, 26);
    // Failures only: the CUSUM climbs 0.908066 per procedure and crosses h1 = 2.291703 at the third.
    EXPECT_EQ(learningCurve(std::vector<bool>(5, true), {}).unacceptableAt, 3);
}

TEST(LearningCurve, RefusesRatesOutOfOrder)
{
    CusumParameters p;
    p.acceptable = 0.2;
    p.unacceptable = 0.1;
    EXPECT_THROW((void)learningCurve({true}, p), colonosim::params::ParameterError);
}

}  // namespace
