#include "simcore/physics/Integrator.h"

#include "simcore/params/Parameter.h"
#include "simcore/physics/BackwardEuler.h"
#include "simcore/physics/ExplicitIntegrators.h"

#include <string>

namespace colonosim::physics {

std::string_view integratorName(IntegratorKind kind)
{
    switch (kind) {
    case IntegratorKind::ExplicitEuler: return "explicit_euler";
    case IntegratorKind::SymplecticEuler: return "symplectic_euler";
    case IntegratorKind::RungeKutta4: return "rk4";
    case IntegratorKind::BackwardEuler: return "backward_euler";
    }
    return "unknown";
}

IntegratorKind parseIntegrator(std::string_view text)
{
    for (const IntegratorKind kind : kAllIntegrators) {
        if (integratorName(kind) == text) {
            return kind;
        }
    }
    throw params::ParameterError("integrator = \"" + std::string(text) +
                                 "\" is not one of explicit_euler, symplectic_euler, rk4, backward_euler");
}

std::unique_ptr<Integrator> makeIntegrator(IntegratorKind kind)
{
    switch (kind) {
    case IntegratorKind::ExplicitEuler: return std::make_unique<ExplicitEuler>();
    case IntegratorKind::SymplecticEuler: return std::make_unique<SymplecticEuler>();
    case IntegratorKind::RungeKutta4: return std::make_unique<RungeKutta4>();
    case IntegratorKind::BackwardEuler: return std::make_unique<BackwardEuler>();
    }
    return std::make_unique<SymplecticEuler>();
}

}  // namespace colonosim::physics
