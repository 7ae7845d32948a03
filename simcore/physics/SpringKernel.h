#pragma once
/// \file
/// The force and damping of a set of springs (SpringSet.h), the colon step's
/// largest term (about half of a loop step's time past the sigmoid): laid out
/// for the processor, with the same bits as the per-spring expression.
///
/// Each spring's force on its first end (the second takes its negative) is
///   f = s d + across dv,  s = (k (l2 / l - L) + along (d.dv / l)) / l,
/// d = x_j - x_i, l2 = (dx dx + dy dy) + dz dz, l = sqrt(l2), dv = v_j - v_i,
/// along = (1 - t) c and across = t c (SpringSet.h). With AVX2 four springs
/// are computed at once, one in each lane; every lane runs the same IEEE
/// operations in the same order as the scalar form (no fused multiply-adds),
/// and the four forces are then added to the nodes one spring after the other
/// in the springs' order. The sums are therefore those of one spring at a
/// time, bit for bit, whichever path runs (tests/physics/SpringKernelTest.cpp).

#include <span>

namespace colonosim::physics {

/// m: a spring shorter than this has no direction and exerts no force.
inline constexpr double kMinSpringLength = 1e-12;

/// One spring as the kernel reads it: its ends, rest length (m), stiffness
/// (N/m) and its damping (N s/m) along the spring, (1 - t) c, and across it, t c.
struct PackedSpring {
    int i, j;
    double rest, k;
    double along, across;
};

/// Which instructions addSpringForces() may use: the widest this processor
/// has (AVX2 where present), or one spring at a time (the reference path).
enum class SpringLanes { Widest, One };

/// Adds each spring's force to f (3 x nodes, column-major, as x and v), in
/// the springs' order. A spring shorter than kMinSpringLength adds none.
void addSpringForces(std::span<const PackedSpring> springs, const double* x, const double* v, double* f,
                     SpringLanes lanes = SpringLanes::Widest);

}  // namespace colonosim::physics
