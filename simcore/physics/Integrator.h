#pragma once
/// \file
/// Time integrators for M dv/dt = f(x, v), dx/dt = v, as pluggable strategies
/// over TissueBody's force interface. Each advances the integrated (free,
/// awake) nodes by one step h. Positional constraints (organs) are applied by
/// the caller once per loop step (TissueSimulation), not per substep.
///   explicit Euler:   x' = x + h v,  v' = v + h M^-1 f(x, v)     (the papers' choice)
///   symplectic Euler: v' = v + h M^-1 f(x, v),  x' = x + h v'
///   RK4:              classical fourth-order Runge-Kutta
///   backward Euler:   (M - h D - h^2 K) dv = h (f(x, v) + h K v), v' = v + dv,
///                     x' = x + h v'; solved by Jacobi-preconditioned conjugate
///                     gradients, matrix-free (Baraff & Witkin 1998).
/// Integrators own their scratch arrays: no allocation once sized.

#include "simcore/physics/TissueBody.h"

#include <memory>
#include <string_view>

namespace colonosim::physics {

enum class IntegratorKind { ExplicitEuler, SymplecticEuler, RungeKutta4, BackwardEuler };
inline constexpr IntegratorKind kAllIntegrators[] = {
    IntegratorKind::ExplicitEuler, IntegratorKind::SymplecticEuler, IntegratorKind::RungeKutta4,
    IntegratorKind::BackwardEuler};

[[nodiscard]] std::string_view integratorName(IntegratorKind kind);
/// Parses "explicit_euler", "symplectic_euler", "rk4", "backward_euler";
/// throws ParameterError naming the value and the allowed names.
[[nodiscard]] IntegratorKind parseIntegrator(std::string_view text);

class Integrator {
public:
    virtual ~Integrator() = default;
    [[nodiscard]] virtual IntegratorKind kind() const = 0;
    /// Advances the body by h seconds.
    virtual void step(TissueBody& body, double h) = 0;
};

[[nodiscard]] std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind);

}  // namespace colonosim::physics
