#pragma once
/// \file
/// The fixed scene of the speed-versus-error report: the default procedural
/// colon (default anatomy and tissue parameters, wall stiffness calibrated on
/// a straight tube of the colon's resolution), gravity with the patient in
/// left lateral position, insufflation at 15 mmHg (2000 Pa), the organs as
/// non-penetrable shapes, and a standard load.
///
/// Standard load: a total force F = 2 N pushing the sigmoid wall outward
/// (radially, away from the centreline) at the mid-sigmoid, shared equally
/// by the free nodes within R = 2 cm of the load point, ramped linearly over
/// T = 0.05 s and then held:  f_i(t) = (F / n) min(t / T, 1) u.

#include "simcore/geometry/ColonAnatomy.h"
#include "simcore/physics/ColonBody.h"

#include <Eigen/Core>

#include <vector>

namespace colonosim::bench {

struct StandardLoad {
    double totalForce = 2.0;                               ///< N
    double rampTime = 0.05;                                ///< s
    double radius = 0.02;                                  ///< m
    Eigen::Vector3d point = Eigen::Vector3d::Zero();       ///< load point on the sigmoid wall, m
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit, out of the lumen
    std::vector<int> nodes;                                ///< loaded free nodes

    /// Force on each loaded node at time t (s), N.
    [[nodiscard]] Eigen::Vector3d nodeForce(double t) const;
    /// Clears the body's external forces and applies the load at time t.
    void apply(physics::TissueBody& body, double t) const;
};

/// The default colon anatomy and everything derived from it once.
struct BenchScene {
    geometry::ColonAnatomy anatomy;
    physics::TissueParameters tissue;
    physics::EnvironmentParameters environment;
    physics::StiffnessCalibration calibration;
    StandardLoad load;

    /// A fresh body at rest (the scene's initial state).
    [[nodiscard]] physics::ColonBody makeBody() const;
};

/// Builds the anatomy, calibrates the wall and places the standard load.
[[nodiscard]] BenchScene buildBenchScene();

}  // namespace colonosim::bench
