// Loop classification on synthetic shafts laid in the default colon: the
// shaft follows the centreline, with a loop inserted where a test wants one.

#include "simcore/procedure/LoopDetector.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace colonosim::procedure {
namespace {

using geometry::Segment;

const geometry::ColonAnatomy& anatomy()
{
    static const geometry::ColonAnatomy instance =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return instance;
}

double segmentMiddle(Segment segment)
{
    const auto& c = anatomy().centreline;
    double lo = 1e9;
    double hi = -1e9;
    for (size_t k = 0; k < c.segment.size(); ++k) {
        if (c.segment[k] == segment) {
            lo = std::min(lo, c.arcLength[k]);
            hi = std::max(hi, c.arcLength[k]);
        }
    }
    return 0.5 * (lo + hi);
}

/// The shapes a test inserts. A curl turns clockwise or counter-clockwise in
/// the anterior view and rises 3 cm towards the front or the back as it goes
/// round, so the curl's end passes in front of or behind the shaft that leads
/// into it: clockwise with the curl in front and counter-clockwise with it
/// behind are left-handed (a reverse alpha loop), the other two
/// right-handed (an alpha: a clockwise spiral along the shaft).
enum class Extra {
    None,
    CurlClockwiseInFront,
    CurlClockwiseBehind,
    CurlCounterClockwiseInFront,
    CurlCounterClockwiseBehind,
    AnteriorBulge
};

bool clockwise(Extra e)
{
    return e == Extra::CurlClockwiseInFront || e == Extra::CurlClockwiseBehind;
}

bool inFront(Extra e)
{
    return e == Extra::CurlClockwiseInFront || e == Extra::CurlCounterClockwiseInFront;
}

/// A shaft along the centreline from the anus to arc length `tipAt`, with an
/// extra shape inserted at `loopAt`, resampled every 2 cm (about the node
/// spacing of an 80-node, 1.7 m scope).
Eigen::Matrix3Xd shaft(double tipAt, double loopAt, Extra extra)
{
    const auto& c = anatomy().centreline;
    std::vector<Eigen::Vector3d> dense;
    for (double s = 0.0; s <= tipAt; s += 0.002) {
        const Eigen::Vector3d p = geometry::sampleCentreline(c, s).point;
        if (extra != Extra::None && std::abs(s - loopAt) < 1e-3) {
            const Eigen::Vector3d t = geometry::sampleCentreline(c, s).tangent;
            Eigen::Vector2d d(t.x(), t.z());
            d.normalize();
            const double side = clockwise(extra) ? -1.0 : 1.0;
            const double rise = inFront(extra) ? -0.03 : 0.03;  // m along y (+: posterior)
            const Eigen::Vector2d n(-d.y() * side,
                                    d.x() * side);  // d rotated by +-90 deg in the anterior view
            constexpr double R = 0.035;             // m
            for (double u = 0.0; u <= 2.0 * std::numbers::pi; u += 0.05) {
                if (extra == Extra::AnteriorBulge) {
                    // Out of the coronal plane, anteriorly and back: 24 cm of shaft
                    // stored without a crossing seen from the front.
                    dense.push_back(p + Eigen::Vector3d(0.0, -0.12 * std::sin(u / 2.0), 0.0));
                } else {
                    // A prolate trochoid, forward along d at its base and back along
                    // its top on the n side: a curl that turns towards n (counter-
                    // clockwise for n = d rotated by +90 deg) and crosses the shaft
                    // leading into it (R > 0.01 m).
                    const Eigen::Vector2d q = (0.01 * u + R * std::sin(u)) * d + R * (1.0 - std::cos(u)) * n;
                    dense.push_back(p + Eigen::Vector3d(q.x(), rise * u / (2.0 * std::numbers::pi), q.y()));
                }
            }
            // The curl ends 2 pi cm ahead along d: the shaft goes on from the
            // centreline that far ahead, the small offset left fading over 5 cm.
            const double ahead = extra == Extra::AnteriorBulge ? 0.0 : 0.02 * std::numbers::pi;
            const Eigen::Vector3d offset = dense.back() - geometry::sampleCentreline(c, s + ahead).point;
            for (double s2 = s + ahead; s2 <= tipAt; s2 += 0.002) {
                dense.push_back(geometry::sampleCentreline(c, s2).point +
                                offset * std::exp(-(s2 - s - ahead) / 0.05));
            }
            break;
        }
        dense.push_back(p);
    }
    std::vector<Eigen::Vector3d> nodes{dense.front()};
    double since = 0.0;
    for (size_t k = 1; k < dense.size(); ++k) {
        since += (dense[k] - dense[k - 1]).norm();
        if (since >= 0.02) {
            nodes.push_back(dense[k]);
            since = 0.0;
        }
    }
    Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(nodes.size()));
    for (size_t k = 0; k < nodes.size(); ++k) {
        out.col(static_cast<Eigen::Index>(k)) = nodes[k];
    }
    return out;
}

double shaftLength(const Eigen::Matrix3Xd& s)
{
    double length = 0.0;
    for (Eigen::Index i = 1; i < s.cols(); ++i) {
        length += (s.col(i) - s.col(i - 1)).norm();
    }
    return length;
}

struct Case {
    const char* label;
    Segment segment;
    Extra extra;
    LoopKind expected;
};

void PrintTo(const Case& c, std::ostream* out)
{
    *out << c.label;
}

class Classification : public ::testing::TestWithParam<Case> {};

TEST_P(Classification, ReadsTheShaftShape)
{
    const Case& c = GetParam();
    const double loopAt = segmentMiddle(c.segment);
    const double tipAt = std::min(loopAt + 0.3, anatomy().centreline.length() - 0.01);
    const Eigen::Matrix3Xd s = shaft(tipAt, loopAt, c.extra);
    LoopDetector detector(anatomy().centreline);
    const LoopKind kind = detector.update(s, shaftLength(s));
    EXPECT_EQ(loopName(kind), loopName(c.expected))
        << "excess " << detector.signals().excessShaft << " m in "
        << geometry::segmentName(detector.signals().segment) << ", crossings " << detector.signals().crossings
        << ", handedness " << detector.signals().handedness << ", turning " << detector.signals().turning;
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, Classification,
    ::testing::Values(Case{"straight_to_the_sigmoid", Segment::Sigmoid, Extra::None, LoopKind::None},
                      Case{"straight_to_the_transverse", Segment::Transverse, Extra::None, LoopKind::None},
                      Case{"alpha", Segment::Sigmoid, Extra::CurlClockwiseBehind, LoopKind::Alpha},
                      Case{"reverse_alpha", Segment::Sigmoid, Extra::CurlClockwiseInFront,
                           LoopKind::ReverseAlpha},
                      // The handedness types the loop, not the way its projection turns.
                      Case{"alpha_seen_counter_clockwise", Segment::Sigmoid,
                           Extra::CurlCounterClockwiseInFront, LoopKind::Alpha},
                      Case{"reverse_alpha_seen_counter_clockwise", Segment::Sigmoid,
                           Extra::CurlCounterClockwiseBehind, LoopKind::ReverseAlpha},
                      Case{"n_loop", Segment::Sigmoid, Extra::AnteriorBulge, LoopKind::N},
                      Case{"deep_transverse", Segment::Transverse, Extra::CurlCounterClockwiseInFront,
                           LoopKind::GammaDeepTransverse}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(LoopDetector, TipThatStopsMovingWithTheShaftIsSeen)
{
    // The shaft is pushed 6 cm further while the tip stays put: a ratio far above 1.
    LoopDetector detector(anatomy().centreline);
    const double at = segmentMiddle(Segment::Sigmoid);
    const Eigen::Matrix3Xd s = shaft(at, 0.0, Extra::None);
    const double length = shaftLength(s);
    detector.update(s, length);
    for (int k = 1; k <= 3; ++k) {
        detector.update(s, length + 0.02 * k);
    }
    EXPECT_GT(detector.signals().tipAdvanceRatio, 10.0);
    // Moving 1:1 gives a ratio near 1.
    LoopDetector moving(anatomy().centreline);
    for (int k = 0; k <= 4; ++k) {
        const Eigen::Matrix3Xd sk = shaft(at + 0.02 * k, 0.0, Extra::None);
        moving.update(sk, shaftLength(sk));
    }
    EXPECT_NEAR(moving.signals().tipAdvanceRatio, 1.0, 0.35);
}

// A scope that bows a mobile colon carries the colon with it: the shaft
// follows the lumen's path, so no segment holds excess shaft, yet more shaft
// is in the patient than the colon's length up to the tip. The insertion
// against the tip's place along the colon reads that stored shaft, as an
// endoscopist reads it; a pleated colon (less shaft in than colon behind the
// tip) stores none.
TEST(LoopDetector, ShaftStoredInAColonThatMovesWithItIsALoop)
{
    const double at = segmentMiddle(Segment::Descending);
    const Eigen::Matrix3Xd s = shaft(at, 0.0, Extra::None);
    const double length = shaftLength(s);
    LoopDetector detector(anatomy().centreline);
    EXPECT_EQ(detector.update(s, length), LoopKind::None);
    EXPECT_NEAR(detector.signals().storedShaft, 0.0, 0.02) << "m: a shaft that follows the colon stores none";
    EXPECT_EQ(detector.update(s, length + 0.05), LoopKind::None) << "5 cm stored: below the 8 cm threshold";
    EXPECT_EQ(detector.update(s, length + 0.12), LoopKind::N);
    EXPECT_NEAR(detector.signals().storedShaft, 0.12, 0.02);
    EXPECT_LT(detector.signals().excessShaft, 0.02) << "m: no segment holds the shaft as excess";
    // Hysteresis: still looped above 60% of the threshold, resolved below it.
    EXPECT_EQ(detector.update(s, length + 0.06), LoopKind::N);
    EXPECT_EQ(detector.update(s, length + 0.03), LoopKind::None);
    // A colon pleated on the shaft: the tip is further along than the shaft is long.
    EXPECT_EQ(detector.update(s, length - 0.20), LoopKind::None);
    EXPECT_LT(detector.signals().storedShaft, -0.15);
}

// A tip hooked back by the dials lies behind the shaft's end along the colon:
// measured at the tip, that reads as shaft stored; measured at the base of
// the bending section, as it is, it does not.
TEST(LoopDetector, AHookedTipIsNotStoredShaft)
{
    const double at = segmentMiddle(Segment::Descending);
    Eigen::Matrix3Xd hooked = shaft(at, 0.0, Extra::None);
    const Eigen::Index n = hooked.cols();
    constexpr Eigen::Index kBent = 5;  // nodes of a 10 cm bending section, 2 cm apart
    const Eigen::Index base = n - 1 - kBent;
    for (Eigen::Index j = 1; j <= kBent; ++j) {
        hooked.col(base + j) = hooked.col(base - j) + Eigen::Vector3d(0.0, -0.01, 0.0);
    }
    const double insertion = shaftLength(hooked);
    LoopDetector atTheTip(anatomy().centreline);
    atTheTip.update(hooked, insertion);
    EXPECT_GT(atTheTip.signals().storedShaft, 0.15) << "m: the hook read as stored shaft at the tip";
    LoopDetector atTheBase(anatomy().centreline);
    atTheBase.setBendingSection(0.10);
    EXPECT_EQ(atTheBase.update(hooked, insertion), LoopKind::None);
    EXPECT_NEAR(atTheBase.signals().storedShaft, 0.0, 0.03);
}

TEST(LoopDetector, LoopResolvesWithHysteresis)
{
    LoopDetector detector(anatomy().centreline);
    const double at = segmentMiddle(Segment::Sigmoid);
    const Eigen::Matrix3Xd looped = shaft(at + 0.3, at, Extra::CurlClockwiseBehind);
    EXPECT_EQ(detector.update(looped, shaftLength(looped)), LoopKind::Alpha);
    const Eigen::Matrix3Xd straight = shaft(at + 0.3, at, Extra::None);
    EXPECT_EQ(detector.update(straight, shaftLength(straight)), LoopKind::None);
}

// A formed loop keeps its type while the reading flickers, and takes a new
// type once that has been read for typeDwell without a break.
TEST(LoopDetector, ALoopsTypeChangesOnlyOnASteadyNewReading)
{
    constexpr int kDwell = 5;
    LoopParameters parameters;
    parameters.typeDwell = kDwell * parameters.analysisInterval;
    ASSERT_EQ(parameters.typeDwellAnalyses(), kDwell);
    LoopDetector detector(anatomy().centreline, parameters);
    const double at = segmentMiddle(Segment::Sigmoid);
    const Eigen::Matrix3Xd alpha = shaft(at + 0.3, at, Extra::CurlClockwiseBehind);
    const Eigen::Matrix3Xd reverse = shaft(at + 0.3, at, Extra::CurlClockwiseInFront);
    ASSERT_EQ(detector.update(alpha, shaftLength(alpha)), LoopKind::Alpha);
    for (int k = 0; k < 12; ++k) {
        const bool flicker = k % 2 == 0;
        const Eigen::Matrix3Xd& s = flicker ? reverse : alpha;
        EXPECT_EQ(detector.update(s, shaftLength(s)), LoopKind::Alpha) << "analysis " << k;
        EXPECT_EQ(detector.signals().reading, flicker ? LoopKind::ReverseAlpha : LoopKind::Alpha);
    }
    for (int k = 1; k < kDwell; ++k) {
        EXPECT_EQ(detector.update(reverse, shaftLength(reverse)), LoopKind::Alpha)
            << "read " << k << " times";
    }
    EXPECT_EQ(detector.update(reverse, shaftLength(reverse)), LoopKind::ReverseAlpha);
    // Resolving is not delayed by the type's dwell.
    const Eigen::Matrix3Xd straight = shaft(at + 0.3, at, Extra::None);
    EXPECT_EQ(detector.update(straight, shaftLength(straight)), LoopKind::None);
}

// The threshold and the hysteresis are the declared parameters, not
// constants: at a 12 cm threshold 9 cm stored is no loop and 15 cm is; with
// resolveFraction 0.5 the loop holds at 7 cm, where the default 60% of 12 cm
// would resolve it, and resolves at 5 cm.
TEST(LoopDetector, TheThresholdAndItsHysteresisAreTheDeclaredParameters)
{
    const double at = segmentMiddle(Segment::Descending);
    const Eigen::Matrix3Xd s = shaft(at, 0.0, Extra::None);
    const double length = shaftLength(s);
    LoopParameters parameters;
    parameters.threshold = 0.12;
    parameters.resolveFraction = 0.5;
    LoopDetector detector(anatomy().centreline, parameters);
    detector.update(s, length);
    const double offset = detector.signals().storedShaft;  // the resampled shaft's own, m
    ASSERT_LT(std::abs(offset), 0.005);
    EXPECT_EQ(detector.update(s, length + 0.09), LoopKind::None);
    EXPECT_EQ(detector.update(s, length + 0.15), LoopKind::N);
    EXPECT_EQ(detector.update(s, length + 0.07), LoopKind::N) << "above half the threshold";
    EXPECT_EQ(detector.update(s, length + 0.05), LoopKind::None) << "below half the threshold";
    parameters.resolveFraction = LoopParameters::resolveFractionSpec.defaultValue;
    LoopDetector withDefaultFraction(anatomy().centreline, parameters);
    EXPECT_EQ(withDefaultFraction.update(s, length + 0.15), LoopKind::N);
    EXPECT_EQ(withDefaultFraction.update(s, length + 0.07), LoopKind::None) << "below 60% of the threshold";
}

TEST(LoopDetector, ParametersOutsideTheirRangeAreRefusedByName)
{
    LoopParameters parameters;
    parameters.threshold = 0.5;
    try {
        LoopDetector detector(anatomy().centreline, parameters);
        FAIL() << "a 0.5 m threshold was accepted";
    } catch (const params::ParameterError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("loops.threshold"), std::string::npos) << what;
        EXPECT_NE(what.find("0.5"), std::string::npos) << what;
        EXPECT_NE(what.find("0.3"), std::string::npos) << what;
    }
    parameters = {};
    parameters.typeDwell = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(LoopDetector(anatomy().centreline, parameters), params::ParameterError);
}

TEST(LoopDetector, CoronalCrossingsOfAFigureEight)
{
    // x = sin t, z = sin t cos t passes the origin at t = 0 and t = pi, both
    // inside the parameter range: one crossing. A circle traced counter-
    // clockwise in the anterior view turns by +2 pi.
    Eigen::Matrix3Xd eight(3, 200);
    Eigen::Matrix3Xd circle(3, 201);
    for (int k = 0; k < 200; ++k) {
        const double t = -1.3 + (2.0 * std::numbers::pi - 0.4) * k / 199.0;
        eight.col(k) = Eigen::Vector3d(std::sin(t), 0.3 * k / 199.0, std::sin(t) * std::cos(t));
    }
    for (int k = 0; k <= 200; ++k) {
        const double t = 2.0 * std::numbers::pi * k / 200.0;
        circle.col(k) = Eigen::Vector3d(std::cos(t), 0.0, std::sin(t));
    }
    EXPECT_EQ(coronalCrossings(eight), 1);
    EXPECT_NEAR(coronalTurning(circle), 2.0 * std::numbers::pi, 0.05);
}

}  // namespace
}  // namespace colonosim::procedure

namespace colonosim::procedure {
namespace {

/// A helix about y (towards the back), `turns` turns of radius 5 cm, drifting
/// along x so that it is seen side on from the front as a row of curls that
/// cross themselves; right-handed for pitch > 0.
Eigen::Matrix3Xd helixAboutY(double pitch)
{
    constexpr int kPoints = 400;
    Eigen::Matrix3Xd h(3, kPoints);
    for (int k = 0; k < kPoints; ++k) {
        const double t = 0.05 * k;
        // (e1, e2, e3) = (z, x, y) is right-handed: cos t e1 + sin t e2 + pitch t e3.
        h.col(k) = Eigen::Vector3d(0.05 * std::sin(t) + 0.025 * t, pitch * t, 0.05 * std::cos(t));
    }
    return h;
}

TEST(LoopDetector, ACrossingsHandednessIsTheHelixsAndNotItsProjections)
{
    for (const double pitch : {0.01, -0.01}) {
        const std::vector<CoronalCrossing> crossings = coronalCrossingList(helixAboutY(pitch));
        ASSERT_EQ(crossings.size(), 3U) << "pitch " << pitch;
        for (const CoronalCrossing& c : crossings) {
            EXPECT_EQ(c.handedness, pitch > 0.0 ? 1 : -1) << "pitch " << pitch << " at " << c.first;
            EXPECT_LT(c.first, c.second);
        }
    }
}

/// A shaft laid along the first metre of the colon's path at rest, a node every 2 cm.
Eigen::Matrix3Xd firstMetreOfRestPath(const geometry::Centreline& centreline)
{
    Eigen::Matrix3Xd follow(3, 51);
    for (Eigen::Index k = 0; k < follow.cols(); ++k) {
        follow.col(k) = geometry::sampleCentreline(centreline, 0.02 * static_cast<double>(k)).point;
    }
    return follow;
}

// The 66 cm redundant sigmoid crosses itself in the anterior view at rest; a
// shaft that follows it crosses itself there too, and that crossing is the
// colon's, not a loop's.
TEST(LoopDetector, AShaftFollowingAColonThatCrossesItselfHasNoCrossingOfItsOwn)
{
    geometry::AnatomyParameters redundant;
    redundant.sigmoidLength = 0.66;
    const geometry::ColonAnatomy colon = geometry::buildProceduralColon(redundant);
    const auto& c = colon.centreline;
    const Eigen::Matrix3Xd follow = firstMetreOfRestPath(c);
    ASSERT_GE(coronalCrossings(follow), 1) << "the redundant sigmoid crosses itself at rest";
    LoopDetector detector(c);
    detector.update(follow, shaftLength(follow));
    EXPECT_EQ(detector.signals().crossings, 0);
    EXPECT_GE(detector.signals().sharedCrossings, 1);
    EXPECT_EQ(detector.current(), LoopKind::None);
}

/// The shaft laid along the rest path of the redundant sigmoid swept either
/// way, with 12 cm of shaft stored behind its tip (above the 8 cm threshold).
LoopDetector storedAlongRedundantSigmoid(double sweep, geometry::ColonAnatomy& colon)
{
    geometry::AnatomyParameters redundant;
    redundant.sigmoidLength = 0.66;
    redundant.sigmoidSweep = sweep;
    colon = geometry::buildProceduralColon(redundant);
    const Eigen::Matrix3Xd follow = firstMetreOfRestPath(colon.centreline);
    LoopDetector detector(colon.centreline);
    detector.update(follow, shaftLength(follow) + 0.12);
    return detector;
}

TEST(LoopDetector, ALoopAlongAColonCrossedAtRestIsTypedByTheShaftsCrossingThere)
{
    // Swept first to the patient's left (counter-clockwise on the anterior
    // view), the sigmoid's limbs cross with the one that leaves it behind:
    // a left-handed crossing, a reverse alpha. Swept to the right, the
    // sigmoid's rest path curls the other way where it meets the descending
    // colon: right-handed, an alpha.
    geometry::ColonAnatomy left;
    const LoopDetector toTheLeft = storedAlongRedundantSigmoid(-1.0, left);
    EXPECT_EQ(toTheLeft.signals().crossings, 0) << "no crossing of its own";
    EXPECT_GE(toTheLeft.signals().sharedCrossings, 1);
    EXPECT_LT(toTheLeft.signals().sharedHandedness, 0);
    EXPECT_EQ(toTheLeft.current(), LoopKind::ReverseAlpha);

    geometry::ColonAnatomy right;
    const LoopDetector toTheRight = storedAlongRedundantSigmoid(1.0, right);
    EXPECT_EQ(toTheRight.signals().crossings, 0);
    EXPECT_GE(toTheRight.signals().sharedCrossings, 1);
    EXPECT_GT(toTheRight.signals().sharedHandedness, 0);
    EXPECT_EQ(toTheRight.current(), LoopKind::Alpha);
}

}  // namespace
}  // namespace colonosim::procedure
