#pragma once
/// \file
/// Calibration of the wall's spring constants against measured tissue
/// response (reference/physical-parameters.md: a mass-spring model does not
/// converge to continuum elasticity by itself).
///
/// Two thin-wall membrane responses of a straight tube of radius r, wall
/// modulus E and thickness t, both uniaxial-stress states (independent of
/// Poisson's ratio):
///   axial:  an axial end load F gives strain eps = F / (2 pi r E t);
///   hoop:   an internal pressure p (open ends) gives dr / r = p r / (E t)
///           (Laplace's law).
/// A tube with the model's ring resolution and spacing is clamped at one end
/// ring; the strains are measured between rings in its middle third, away from
/// end effects, by static equilibrium. The axial and circumferential factors
/// are updated by the ratio of measured to target stiffness until both
/// responses match (the shear springs couple them). The axial target is
/// tissue.haustralAxialRatio x E t: a haustrated wall is a bellows, far
/// softer along the colon than around it (TissueParameters.h).

#include "simcore/physics/ColonBody.h"

namespace colonosim::physics {

struct TubeResolution {
    int nodesPerRing = 16;
    double radius = 0.02;        ///< m
    double ringSpacing = 0.014;  ///< m
    int rings = 30;
};

struct CalibrationReport {
    StiffnessCalibration factors;
    double axialStiffnessError = 0.0;  ///< relative error of the effective E t, axial (1)
    double hoopStiffnessError = 0.0;   ///< relative error of the effective E t, hoop (1)
    int iterations = 0;
};

/// Effective membrane stiffness E t (N/m) of the model tube, measured axially
/// and circumferentially with the given factors.
struct MeasuredStiffness {
    double axial = 0.0;
    double hoop = 0.0;
};
[[nodiscard]] MeasuredStiffness measureTubeStiffness(const TubeResolution& tube,
                                                     const TissueParameters& tissue,
                                                     const StiffnessCalibration& factors);

/// Finds the factors that make the effective axial stiffness equal
/// tissue.haustralAxialRatio x E t and the hoop stiffness E t, each within
/// `tolerance` (relative).
[[nodiscard]] CalibrationReport
calibrateWallStiffness(const TubeResolution& tube, const TissueParameters& tissue, double tolerance = 1e-3);

/// Bending rigidity (N m^2) of the model tube as a beam: a pure end moment M
/// (axial loads on the last ring in proportion to each node's distance from
/// the bending axis) bends it to a curvature kappa, measured from the tilt of
/// the rings at one and two thirds of its length; EI = M / kappa. A thin-walled
/// tube of axial membrane stiffness E_a t bends with EI = pi r^3 E_a t.
[[nodiscard]] double measureTubeBendingRigidity(const TubeResolution& tube, const TissueParameters& tissue,
                                                const StiffnessCalibration& factors);

/// The factors for `tissue` given `isotropic`, factors calibrated for a wall
/// with tissue.haustralAxialRatio 1 (ProcedureSettings::calibration): those
/// themselves at ratio 1, else scaled by the ratio of the factors that
/// calibrateWallStiffness() finds for the default TubeResolution with the
/// tissue's ratio to those it finds with 1. Throws params::ParameterError
/// when the calibration does not reach its tolerance. The factors found are
/// kept for the process by the tissue (the last 8 tissues): every procedure
/// on the same tissue asks for the same ones, about 4 s each.
[[nodiscard]] StiffnessCalibration wallCalibrationFor(const TissueParameters& tissue,
                                                      const StiffnessCalibration& isotropic);

/// A straight tube along +z, rings of `nodesPerRing`, quads split along one diagonal.
[[nodiscard]] geometry::TriangleMesh makeStraightTube(const TubeResolution& tube);

}  // namespace colonosim::physics
