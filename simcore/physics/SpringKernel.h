#pragma once
/// \file
/// The force and damping of a set of springs (SpringSet.h), the colon step's
/// largest term (about half of a loop step's time past the sigmoid): laid out
/// for the processor, with the same bits as the per-spring expression.
///
/// Each spring's force on its first end (the second takes its negative) is
///   f = s d + across dv,  s = (k (l2 / l - L) + along (d.dv / l)) / l,
/// d = x_j - x_i, l2 = (dx dx + dy dy) + dz dz, l = sqrt(l2), dv = v_j - v_i,
/// along = (1 - t) c and across = t c (SpringSet.h). It runs in two passes.
///  1. Every spring's force, each independent of the others: with AVX2 four
///     springs at once, one in each lane, every lane running the same IEEE
///     operations in the same order as the scalar form (no fused
///     multiply-adds), into a per-spring scratch.
///  2. Each node sums its springs' forces in the springs' order
///     (NodeGather.h): the same additions in the same order as adding one
///     spring after the other, so the sums are the same bit for bit
///     (tests/physics/SpringKernelTest.cpp).

#include "simcore/physics/NodeGather.h"

#include <span>
#include <vector>

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

/// The second pass's order (each node's springs in the springs' order) and
/// the first pass's per-spring scratch. Depends only on the springs' ends and
/// order: rebuild it when springs are added, removed or reordered.
class SpringGather {
public:
    /// From the springs' ends, in their order.
    void build(std::span<const PackedSpring> springs);
    [[nodiscard]] size_t numSprings() const { return m_nodes.numItems(); }

private:
    friend void addSpringForces(std::span<const PackedSpring>, SpringGather&, const double*, const double*,
                                double*, SpringLanes);
    NodeGather m_nodes;
    std::vector<int> m_ends;  ///< build()'s springs' ends, kept for its storage
    // Pass 1's results, per spring: squared length (m^2) and force on the first end (N).
    std::vector<double> m_l2, m_fx, m_fy, m_fz;
};

/// Adds each spring's force to f (3 x nodes, column-major, as x and v), with
/// the sums of adding them in the springs' order. A spring shorter than
/// kMinSpringLength adds none. `gather` must have been built from `springs`.
void addSpringForces(std::span<const PackedSpring> springs, SpringGather& gather, const double* x,
                     const double* v, double* f, SpringLanes lanes = SpringLanes::Widest);

}  // namespace colonosim::physics
