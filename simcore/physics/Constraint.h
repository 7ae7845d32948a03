#pragma once
/// \file
/// A positional constraint applied after each integration step (e.g. organs
/// the wall may not penetrate): it projects positions back to the allowed
/// region and removes the velocity component that points into the forbidden one.

#include "simcore/physics/ForceTerm.h"

#include <span>
#include <string_view>

namespace colonosim::physics {

class Constraint {
public:
    virtual ~Constraint() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;
    /// Projects the listed nodes; returns how many were corrected.
    virtual int project(std::span<const int> nodes, Positions& x, Velocities& v) const = 0;
};

}  // namespace colonosim::physics
