// The documented calibration of the wall springs (docs/calibration.md).

#include "simcore/physics/SpringCalibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace colonosim::physics {
namespace {

TEST(Calibration, ReproducesAxialAndHoopMembraneStiffness)
{
    // Target: E t = 1.74 MPa x 2 mm = 3480 N/m in both directions, within 0.1%.
    const TissueParameters tissue;
    const TubeResolution tube;
    const CalibrationReport report = calibrateWallStiffness(tube, tissue, 1e-3);
    EXPECT_LT(std::abs(report.axialStiffnessError), 1e-3);
    EXPECT_LT(std::abs(report.hoopStiffnessError), 1e-3);
    EXPECT_GT(report.factors.axial, 0.1);
    EXPECT_LT(report.factors.axial, 10.0);
    const MeasuredStiffness uncalibrated = measureTubeStiffness(tube, tissue, StiffnessCalibration{});
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    // The raw Van Gelder constants are off by more than the tolerance, so the
    // calibration has work to do.
    EXPECT_GT(std::abs(uncalibrated.axial / et - 1.0) + std::abs(uncalibrated.hoop / et - 1.0), 1e-2);
}

TEST(Calibration, FactorsTransferToAScaledTubeAndAnotherModulus)
{
    // The factors depend on the mesh's shape (ring spacing over node spacing)
    // and the spring ratios, not on size or modulus: a tube twice as large
    // with a stiffer wall keeps the calibrated response within 1%.
    TissueParameters tissue;
    const TubeResolution tube;
    const CalibrationReport report = calibrateWallStiffness(tube, tissue, 1e-3);
    TubeResolution larger = tube;
    larger.radius *= 2.0;
    larger.ringSpacing *= 2.0;
    tissue.wallYoungModulus = 5.18e6;
    const MeasuredStiffness m = measureTubeStiffness(larger, tissue, report.factors);
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    EXPECT_NEAR(m.axial / et, 1.0, 0.01);
    EXPECT_NEAR(m.hoop / et, 1.0, 0.01);
}

/// The colonoscope's flexural rigidity, N m^2: 0.026-0.040 along the
/// insertion tube (reference/physical-parameters.md).
constexpr double kScopeRigidityLow = 0.026;

TEST(Calibration, TheCalibratedTubeBendsAsAThinWalledBeamStifferThanTheScope)
{
    // A thin-walled tube of membrane stiffness E t bends with EI = pi r^3 E t:
    // the calibrated flat wall gives it within 3%. At the default 2 cm radius
    // that is over twice the scope's rigidity: such a colon guides the scope
    // like a pipe (TissueParameters::haustralAxialSpec).
    const TissueParameters tissue;
    const TubeResolution tube;
    const CalibrationReport report = calibrateWallStiffness(tube, tissue, 1e-3);
    const double ei = measureTubeBendingRigidity(tube, tissue, report.factors);
    const double beam =
        std::numbers::pi * std::pow(tube.radius, 3) * tissue.wallYoungModulus * tissue.wallThickness;
    EXPECT_NEAR(ei / beam, 1.0, 0.03) << "EI " << ei << " N m^2 against pi r^3 E t " << beam;
    EXPECT_GT(ei, 2.0 * kScopeRigidityLow);
}

TEST(Calibration, AHaustralWallIsSofterAlongAndInBendingButNotAround)
{
    // With the axial target a fraction of E t the calibration still meets
    // both targets; the tube's bending rigidity follows the axial stiffness
    // and the hoop (insufflation) compliance stays that of E t.
    TissueParameters tissue;
    tissue.haustralAxialRatio = 0.07;
    const TubeResolution tube;
    const CalibrationReport report = calibrateWallStiffness(tube, tissue, 1e-3);
    ASSERT_LT(std::abs(report.axialStiffnessError), 1e-3);
    ASSERT_LT(std::abs(report.hoopStiffnessError), 1e-3);
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    const MeasuredStiffness m = measureTubeStiffness(tube, tissue, report.factors);
    EXPECT_NEAR(m.axial / et, 0.07, 0.07 * 2e-3);
    EXPECT_NEAR(m.hoop / et, 1.0, 2e-3);
    const double ei = measureTubeBendingRigidity(tube, tissue, report.factors);
    const double beam = std::numbers::pi * std::pow(tube.radius, 3) * 0.07 * et;
    EXPECT_NEAR(ei / beam, 1.0, 0.1) << "EI " << ei << " N m^2 against pi r^3 0.07 E t " << beam;
    EXPECT_LT(ei, 0.5 * kScopeRigidityLow);
}

TEST(Calibration, TheRunsFactorsAreTheGivenOnesForAFlatWallAndScaledForAHaustralOne)
{
    TissueParameters tissue;
    const StiffnessCalibration given{0.5, 0.97};
    const StiffnessCalibration flat = wallCalibrationFor(tissue, given);
    EXPECT_EQ(flat.axial, given.axial);
    EXPECT_EQ(flat.circumferential, given.circumferential);
    tissue.haustralAxialRatio = 0.07;
    const StiffnessCalibration folded = wallCalibrationFor(tissue, given);
    const CalibrationReport direct = calibrateWallStiffness(TubeResolution{}, tissue, 1e-3);
    const CalibrationReport reference = calibrateWallStiffness(TubeResolution{}, TissueParameters{}, 1e-3);
    EXPECT_DOUBLE_EQ(folded.axial, given.axial * direct.factors.axial / reference.factors.axial);
    EXPECT_DOUBLE_EQ(folded.circumferential, given.circumferential * direct.factors.circumferential /
                                                 reference.factors.circumferential);
    EXPECT_LT(folded.axial, 0.2 * given.axial);
}

// A haustral wall's calibration is made once per tissue and kept for the
// process (every procedure on the same tissue asks for the same one): asked
// again, the same tissue and given factors get the same factors bit for bit;
// other given factors are scaled by the same calibration, and another ratio
// is calibrated for itself.
TEST(Calibration, AHaustralWallsCalibrationIsKeptByItsTissueAndGivenFactors)
{
    TissueParameters tissue;
    tissue.haustralAxialRatio = 0.07;
    const StiffnessCalibration given{0.5, 0.97};
    const StiffnessCalibration first = wallCalibrationFor(tissue, given);
    TissueParameters other = tissue;
    other.haustralAxialRatio = 0.3;
    const StiffnessCalibration softer = wallCalibrationFor(other, given);
    EXPECT_GT(softer.axial, first.axial) << "a ratio of 0.3 is its own calibration";
    const StiffnessCalibration unit = wallCalibrationFor(tissue, StiffnessCalibration{});
    EXPECT_DOUBLE_EQ(unit.axial, first.axial / given.axial) << "other given factors scale their own";
    EXPECT_DOUBLE_EQ(unit.circumferential, first.circumferential / given.circumferential);
    const StiffnessCalibration again = wallCalibrationFor(tissue, given);
    EXPECT_EQ(again.axial, first.axial);
    EXPECT_EQ(again.circumferential, first.circumferential);
}

TEST(Calibration, AHaustralRatioOutsideItsRangeIsRefusedByName)
{
    TissueParameters tissue;
    tissue.haustralAxialRatio = 0.001;
    try {
        tissue.validate();
        FAIL() << "a ratio of 0.001 was accepted";
    } catch (const params::ParameterError& error) {
        EXPECT_NE(std::string(error.what()).find("tissue.haustralAxialRatio = 0.001"), std::string::npos)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("[0.01, 1]"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace colonosim::physics
