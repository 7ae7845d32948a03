#pragma once
/// \file
/// The explicit integrators; equations in Integrator.h.

#include "simcore/physics/Integrator.h"

namespace colonosim::physics {

class ExplicitEuler final : public Integrator {
public:
    [[nodiscard]] IntegratorKind kind() const override { return IntegratorKind::ExplicitEuler; }
    void step(TissueBody& body, double h) override;

private:
    Forces m_f;
};

class SymplecticEuler final : public Integrator {
public:
    [[nodiscard]] IntegratorKind kind() const override { return IntegratorKind::SymplecticEuler; }
    void step(TissueBody& body, double h) override;

private:
    Forces m_f;
};

class RungeKutta4 final : public Integrator {
public:
    [[nodiscard]] IntegratorKind kind() const override { return IntegratorKind::RungeKutta4; }
    void step(TissueBody& body, double h) override;

private:
    Positions m_x0, m_xs, m_dx;
    Velocities m_v0, m_vs, m_dv;
    Forces m_f;
};

}  // namespace colonosim::physics
