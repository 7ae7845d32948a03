#pragma once
// For the force kernels' tests (SpringKernelTest, PressureKernelTest): how
// many components of two force fields (or row sums) differ in their bits.

#include "simcore/physics/ForceTerm.h"

#include <bit>
#include <cstdint>

namespace colonosim::physics::testing {

/// Components of `actual` whose bits differ from `expected`'s (the two of one
/// size): force fields, row sums, any plain Eigen array of doubles.
template <class Expected, class Actual>
int differingBits(const Eigen::PlainObjectBase<Expected>& expected,
                  const Eigen::PlainObjectBase<Actual>& actual)
{
    int differing = 0;
    for (Eigen::Index k = 0; k < expected.size(); ++k) {
        differing +=
            std::bit_cast<std::uint64_t>(expected.data()[k]) != std::bit_cast<std::uint64_t>(actual.data()[k])
                ? 1
                : 0;
    }
    return differing;
}

}  // namespace colonosim::physics::testing
