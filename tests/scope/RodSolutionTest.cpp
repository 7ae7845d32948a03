// The discrete rod against the reference solutions of
// reference/physical-parameters.md (small deflection, end-moment arc,
// large-deflection elastica) with both solvers, its convergence with the
// element count, and the chain solver against the Newton reference.

#include "simcore/scope/Cantilever.h"
#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/ReferenceSolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using colonosim::scope::CantileverLoads;
using colonosim::scope::DiscreteRod;
using colonosim::scope::makeCantilever;
using colonosim::scope::solveChain;
using colonosim::scope::solveReference;
using colonosim::scope::tipAngle;

constexpr double kLength = 1.0;
constexpr double kEI = 0.033;  // the scope's default EI, N m^2
constexpr double kGJ = 0.44;
constexpr int kDefaultElements = 79;  // 80 nodes, the scope's default

enum class Solver { Chain, Reference };

struct Tip {
    double u = 0.0;  ///< shortening / L
    double v = 0.0;  ///< deflection / L (downwards positive)
    double angle = 0.0;
    double residual = 0.0;
};

Tip solve(Solver solver, int elements, const CantileverLoads& loads, int iterations = 2000)
{
    DiscreteRod rod = makeCantilever(elements, kLength, kEI, kGJ, loads);
    Tip tip;
    if (solver == Solver::Chain) {
        tip.residual = solveChain(rod, iterations, 0.5);
    } else {
        const auto result = solveReference(rod);
        EXPECT_TRUE(result.converged) << "gradient " << result.gradientNorm;
        tip.residual = result.gradientNorm;
    }
    const Eigen::Vector3d x = rod.position.back();
    tip.u = 1.0 - x.x() / kLength;
    tip.v = -x.y() / kLength;
    tip.angle = tipAngle(rod);
    return tip;
}

const char* name(Solver s)
{
    return s == Solver::Chain ? "chain" : "reference";
}

// Small deflection: P L^2 / EI = 1e-4, so the geometric nonlinearity (relative
// O(alpha^2) ~ 1e-8) and the midpoint rule's O(1/n^2) ~ 1e-4 relative error
// are both far below the 0.1% tolerance.
TEST(RodSolution, SmallDeflectionMatchesBeamTheory)
{
    const double p = 1e-4 * kEI / (kLength * kLength);
    for (Solver solver : {Solver::Chain, Solver::Reference}) {
        const Tip tip = solve(solver, kDefaultElements, {.tipLoad = p});
        const double v = p * std::pow(kLength, 3) / (3.0 * kEI) / kLength;
        const double angle = p * kLength * kLength / (2.0 * kEI);
        EXPECT_NEAR(tip.v, v, 1e-3 * v) << name(solver);
        EXPECT_NEAR(tip.angle, angle, 1e-3 * angle) << name(solver);
    }
}

// End moment: the tip angle is exact for the discrete rod (joint compliances
// sum to L / EI); positions carry the chord error 1 - sinc(t/(2n)) ~ 1e-5 at
// n = 79, so 1e-4 relative.
TEST(RodSolution, EndMomentGivesCircularArc)
{
    for (double t : {0.5, 1.0, 1.5707963, 2.5}) {
        for (Solver solver : {Solver::Chain, Solver::Reference}) {
            const Tip tip = solve(solver, kDefaultElements, {.endMoment = t * kEI / kLength});
            EXPECT_NEAR(tip.angle, t, 1e-9) << name(solver) << " t=" << t;
            EXPECT_NEAR(tip.u, 1.0 - std::sin(t) / t, 1e-4 * t) << name(solver) << " t=" << t;
            EXPECT_NEAR(tip.v, (1.0 - std::cos(t)) / t, 1e-4 * t) << name(solver) << " t=" << t;
        }
    }
}

struct ElasticaCase {
    double alpha;
    double v;
    double u;
};

// Bisshopp & Drucker 1945 (physical-parameters.md), within 1% at 80 nodes.
TEST(RodSolution, LargeDeflectionMatchesElasticaTable)
{
    for (const ElasticaCase c : {ElasticaCase{1.0, 0.30172, 0.05643}, ElasticaCase{2.0, 0.49346, 0.16064}}) {
        for (Solver solver : {Solver::Chain, Solver::Reference}) {
            const Tip tip = solve(solver, kDefaultElements, {.tipLoad = c.alpha * kEI / (kLength * kLength)});
            EXPECT_NEAR(tip.v, c.v, 0.01 * c.v) << name(solver) << " alpha=" << c.alpha;
            EXPECT_NEAR(tip.u, c.u, 0.01 * c.u) << name(solver) << " alpha=" << c.alpha;
            std::printf("alpha %.0f %-9s v/L %.6f (err %.2e) u/L %.6f (err %.2e)\n", c.alpha, name(solver),
                        tip.v, tip.v / c.v - 1.0, tip.u, tip.u / c.u - 1.0);
        }
    }
}

}  // namespace
