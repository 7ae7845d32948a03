// lumenSelfOverlap (ColonLayout.h): two parts of the lumen far apart along the
// colon that pass through each other, and never two parts of one bend.

#include "simcore/geometry/ColonLayout.h"

#include <gtest/gtest.h>

#include <numbers>

namespace colonosim::geometry {
namespace {

constexpr double kRadius = 0.014;  // m, a typical distended lumen

/// A hairpin: out along +x for `leg` metres, round a half circle of radius
/// `apart` / 2, and back along -x, `apart` metres from the way out; sampled
/// every 5 mm.
Centreline hairpin(double leg, double apart)
{
    Centreline c;
    const double bend = std::numbers::pi * apart / 2.0;
    const double total = 2.0 * leg + bend;
    for (double s = 0.0; s <= total + 1e-12; s += 0.005) {
        Eigen::Vector3d p;
        if (s <= leg) {
            p = {s, 0.0, 0.0};
        } else if (s <= leg + bend) {
            const double a = (s - leg) / (apart / 2.0);
            p = {leg + apart / 2.0 * std::sin(a), apart / 2.0 * (1.0 - std::cos(a)), 0.0};
        } else {
            p = {leg - (s - leg - bend), apart, 0.0};
        }
        c.points.push_back(p);
        c.arcLength.push_back(s);
        c.radius.push_back(kRadius);
    }
    return c;
}

TEST(LumenSelfOverlap, LimbsCloserThanTwoRadiiOverlapByTheDifference)
{
    // Limbs 20 mm apart, centre to centre: 8 mm of overlap along the legs,
    // less what the samples of the way back lie off those of the way out
    // (up to 2.5 mm along x: sqrt(20^2 + 2.5^2) - 20 = 0.16 mm).
    const LumenSelfOverlap overlap = lumenSelfOverlap(hairpin(0.2, 0.020));
    EXPECT_GT(overlap.pairs, 0);
    EXPECT_LE(overlap.deepest, 2.0 * kRadius - 0.020);
    EXPECT_GT(overlap.deepest, 2.0 * kRadius - 0.020 - 0.16e-3);
    EXPECT_LT(overlap.arcA, overlap.arcB);
}

TEST(LumenSelfOverlap, LimbsThatOnlyTouchOrLieApartDoNot)
{
    EXPECT_EQ(lumenSelfOverlap(hairpin(0.2, 2.0 * kRadius)).pairs, 0) << "touching is allowed";
    EXPECT_EQ(lumenSelfOverlap(hairpin(0.2, 0.040)).pairs, 0);
}

TEST(LumenSelfOverlap, APartOfOneBendIsNeverPairedWithItself)
{
    // A tight circle's samples overlap their neighbours within 2 (r_i + r_j)
    // along it; with legs too short to come back past that, nothing counts.
    EXPECT_EQ(lumenSelfOverlap(hairpin(0.0, 0.030)).pairs, 0);
}

TEST(LumenSelfOverlap, TheDefaultColonDoesNotPassThroughItself)
{
    EXPECT_EQ(lumenSelfOverlap(layoutColon(AnatomyParameters{}).centreline).pairs, 0);
}

}  // namespace
}  // namespace colonosim::geometry
