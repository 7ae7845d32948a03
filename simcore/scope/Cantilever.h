#pragma once
/// \file
/// The cantilever test case of reference/physical-parameters.md ("Rod
/// (colonoscope) reference solutions"): a discrete rod clamped at the origin
/// along +x, with dead loads in -y: a tip load P, a distributed load q per
/// metre (lumped to the nodes: q l inside, q l / 2 at the tip) and an end
/// moment M bending the rod the same way (torque -M about +z). Used by the
/// `colonosim rod` command, the tests and the benchmark.

#include "simcore/scope/DiscreteRod.h"

namespace colonosim::scope {

struct CantileverLoads {
    double tipLoad = 0.0;          ///< P, N (downwards)
    double distributedLoad = 0.0;  ///< q, N/m (downwards)
    double endMoment = 0.0;        ///< M, N m (bending downwards)
    double tipTorque = 0.0;        ///< T about the rod's axis (+x), N m
};

/// A straight rod of `numElements` elements clamped at the origin along +x
/// (frame columns right = -z, up = +y, forward = +x), loads applied.
[[nodiscard]] DiscreteRod makeCantilever(int numElements, double length, double flexuralRigidity,
                                         double torsionalRigidity, const CantileverLoads& loads);

/// Angle of the tip tangent below +x, rad (atan2(-t_y, t_x) of the tip frame's forward column).
[[nodiscard]] double tipAngle(const DiscreteRod& rod);

}  // namespace colonosim::scope
