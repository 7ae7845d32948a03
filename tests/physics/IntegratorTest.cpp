// Integrators against the closed-form damped oscillator (PyElastica's and
// SOFA's habit): one node of mass m on an anchor spring k with damping c.
// x(t) = e^{-zeta w t} (x0 cos(wd t) + (zeta w x0 / wd) sin(wd t)), v(0) = 0.

#include "simcore/physics/Integrator.h"
#include "simcore/physics/AnchorSprings.h"
#include "simcore/physics/BackwardEuler.h"
#include "simcore/physics/TissueBody.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace colonosim::physics {
namespace {

constexpr double kMass = 2e-3;                           // kg
constexpr double kOmega = 2.0 * std::numbers::pi * 2.0;  // rad/s
constexpr double kX0 = 0.01;                             // m

TissueBody makeOscillator(double zeta)
{
    TissueBody body(Positions::Constant(3, 1, 0.0), Eigen::VectorXd::Constant(1, kMass));
    auto anchor = std::make_unique<AnchorSprings>();
    anchor->add(0, Eigen::Vector3d::Zero(), kMass * kOmega * kOmega, 2.0 * zeta * kOmega * kMass);
    body.addForceTerm(std::move(anchor));
    body.positions().col(0) = Eigen::Vector3d(kX0, 0.0, 0.0);
    return body;
}

double exact(double zeta, double t)
{
    const double wd = kOmega * std::sqrt(1.0 - zeta * zeta);
    return std::exp(-zeta * kOmega * t) *
           (kX0 * std::cos(wd * t) + zeta * kOmega * kX0 / wd * std::sin(wd * t));
}

/// Largest error over the trajectory, sampled every 10 ms (a common grid
/// for all step sizes; the error at a single instant oscillates with phase).
double errorAt(IntegratorKind kind, double zeta, double h, double duration)
{
    TissueBody body = makeOscillator(zeta);
    auto integrator = makeIntegrator(kind);
    const int steps = static_cast<int>(std::lround(duration / h));
    const int stride = static_cast<int>(std::lround(0.01 / h));
    double largest = 0.0;
    for (int s = 1; s <= steps; ++s) {
        integrator->step(body, h);
        if (s % stride == 0) {
            largest = std::max(largest, std::abs(body.positions()(0, 0) - exact(zeta, s * h)));
        }
    }
    return largest;
}

struct OrderCase {
    IntegratorKind kind;
    double expectedOrder;
    double coarseStep;  ///< s
};

void PrintTo(const OrderCase& c, std::ostream* out)
{
    *out << integratorName(c.kind);
}

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, MatchesTheMethodsOrder)
{
    // Observed order from three step sizes, each half the previous; the
    // asymptotic regime is reached when the two estimates agree. Tolerance
    // 0.15 on the order: the next error term changes it by O(h) at these steps.
    const OrderCase& c = GetParam();
    constexpr double zeta = 0.05;
    constexpr double duration = 1.0;
    const double e1 = errorAt(c.kind, zeta, c.coarseStep, duration);
    const double e2 = errorAt(c.kind, zeta, c.coarseStep / 2, duration);
    const double e3 = errorAt(c.kind, zeta, c.coarseStep / 4, duration);
    const double order12 = std::log2(e1 / e2);
    const double order23 = std::log2(e2 / e3);
    std::cout << integratorName(c.kind) << ": max errors " << e1 << ", " << e2 << ", " << e3
              << " m; observed orders " << order12 << ", " << order23 << '\n';
    EXPECT_NEAR(order23, c.expectedOrder, 0.15) << "errors " << e1 << ", " << e2 << ", " << e3;
    EXPECT_NEAR(order12, c.expectedOrder, 0.3) << "errors " << e1 << ", " << e2 << ", " << e3;
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, ConvergenceOrder,
                         ::testing::Values(OrderCase{IntegratorKind::ExplicitEuler, 1.0, 1e-3},
                                           OrderCase{IntegratorKind::SymplecticEuler, 1.0, 1e-3},
                                           OrderCase{IntegratorKind::RungeKutta4, 4.0, 5e-3},
                                           OrderCase{IntegratorKind::BackwardEuler, 1.0, 1e-3}),
                         [](const auto& info) { return std::string(integratorName(info.param.kind)); });

TEST(SymplecticEuler, EnergyStaysBoundedOverTenMinutesUndamped)
{
    // 600,000 steps of 1 ms (10 minutes at the loop rate) with omega h = 0.025.
    // Symplectic Euler conserves a modified energy, so the true energy only
    // oscillates, with relative amplitude about omega h / 2 = 0.0126; it must
    // neither drift nor grow. Explicit Euler at the same step gains energy by
    // (1 + (omega h)^2) per step, i.e. e^{375} over the run: it is reported
    // as the contrast, not simulated for 10 minutes.
    TissueBody body = makeOscillator(0.0);
    auto integrator = makeIntegrator(IntegratorKind::SymplecticEuler);
    const double e0 = body.potentialEnergy();
    constexpr double h = 1e-3;
    double maxDeviation = 0.0;
    double firstMinuteMean = 0.0;
    double lastMinuteMean = 0.0;
    constexpr int stepsPerMinute = 60000;
    for (int s = 0; s < 10 * stepsPerMinute; ++s) {
        integrator->step(body, h);
        const double e = body.kineticEnergy() + body.potentialEnergy();
        maxDeviation = std::max(maxDeviation, std::abs(e - e0) / e0);
        if (s < stepsPerMinute) {
            firstMinuteMean += e / stepsPerMinute;
        } else if (s >= 9 * stepsPerMinute) {
            lastMinuteMean += e / stepsPerMinute;
        }
    }
    std::cout << "symplectic Euler, 10 min undamped: max relative energy deviation " << maxDeviation
              << ", last/first minute mean " << lastMinuteMean / firstMinuteMean << '\n';
    EXPECT_LT(maxDeviation, 0.5 * kOmega * h * 1.05);
    EXPECT_NEAR(lastMinuteMean / firstMinuteMean, 1.0, 1e-6) << "energy drifted";
}

TEST(ExplicitEuler, GainsEnergyWithoutDamping)
{
    TissueBody body = makeOscillator(0.0);
    auto integrator = makeIntegrator(IntegratorKind::ExplicitEuler);
    const double e0 = body.potentialEnergy();
    for (int s = 0; s < 10000; ++s) {
        integrator->step(body, 1e-3);
    }
    const double e = body.kineticEnergy() + body.potentialEnergy();
    // (1 + (omega h)^2)^10000 = e^{6.3} ~ 540
    EXPECT_NEAR(std::log(e / e0), 10000 * std::log1p(std::pow(kOmega * 1e-3, 2)), 0.01);
}

TEST(BackwardEuler, IsStableFarBeyondTheExplicitLimit)
{
    TissueBody body = makeOscillator(0.0);
    BackwardEuler integrator;
    const double h = 100.0 / kOmega;  // 50x the symplectic limit 2/omega
    double previous = body.potentialEnergy();
    for (int s = 0; s < 50; ++s) {
        integrator.step(body, h);
        const double e = body.kineticEnergy() + body.potentialEnergy();
        EXPECT_LE(e, previous * (1.0 + 1e-12)) << "backward Euler must not gain energy";
        previous = e;
    }
    EXPECT_TRUE(body.positions().allFinite());
}

}  // namespace
}  // namespace colonosim::physics
