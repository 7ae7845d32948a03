// The chain solver and the rod's rebuild, as optimised, against a plain
// transcription of eqs 1-7 kept here: the same floating-point operations in
// the same order, so the two must agree to the last bit (recorded procedures
// replay, and long regression runs, depend on it). Compared bit for bit on
// every coordinate of every node, every step, over a loaded, dialled,
// damped scope.

#include "simcore/scope/Cantilever.h"
#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/Colonoscope.h"
#include "simcore/scope/Rotation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace {

using colonosim::scope::Colonoscope;
using colonosim::scope::DiscreteRod;
using colonosim::scope::ScopeParameters;
using colonosim::scope::solveChain;

// --- The reference: eqs 1-7 written out directly, one joint at a time. ---

/// Rodrigues' formula with (a, b) one at a time: below |theta| = 0.6 rad the
/// Taylor series in t^2 by Estrin's scheme, with the coefficients 1/(2k+1)! and
/// 1/(2k+2)! written out; above, sin and cos. The matrix is then Rotation.h's.
Eigen::Matrix3d referenceRotation(const Eigen::Vector3d& theta)
{
    const double t2 = theta.squaredNorm();
    double a = 0.0;
    double b = 0.0;
    if (t2 < 0.36) {
        const double fa[8] = {1.0 / 1.0,      -1.0 / 6.0,        1.0 / 120.0,        -1.0 / 5040.0,
                              1.0 / 362880.0, -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0};
        const double fb[8] = {
            1.0 / 2.0,       -1.0 / 24.0,        1.0 / 720.0,         -1.0 / 40320.0,
            1.0 / 3628800.0, -1.0 / 479001600.0, 1.0 / 87178291200.0, -1.0 / 20922789888000.0};
        // Estrin's scheme: ((c0 + c1 t2) + (c2 + c3 t2) t4) + ((c4 + c5 t2) + (c6 + c7 t2) t4) t8.
        const double t4 = t2 * t2;
        const double t8 = t4 * t4;
        const auto estrin = [&](const double* c) {
            return ((c[0] + c[1] * t2) + (c[2] + c[3] * t2) * t4) +
                   ((c[4] + c[5] * t2) + (c[6] + c[7] * t2) * t4) * t8;
        };
        a = estrin(fa);
        b = estrin(fb);
    } else {
        const double t = std::sqrt(t2);
        a = std::sin(t) / t;
        b = (1.0 - std::cos(t)) / t2;
    }
    return colonosim::scope::rotationFromCoefficients(theta, Eigen::Array2d(a, b));
}

void referenceRebuild(DiscreteRod& rod)
{
    Eigen::Vector3d x = rod.basePosition + rod.stubLength * rod.baseFrame.col(2);
    Eigen::Matrix3d before = rod.baseFrame;
    for (int k = 0; k < rod.numNodes(); ++k) {
        const auto i = static_cast<size_t>(k);
        rod.position[i] = x;
        const Eigen::Matrix3d joint = rod.hasDial[i]
                                          ? Eigen::Matrix3d(rod.dial[i] * referenceRotation(rod.theta[i]))
                                          : referenceRotation(rod.theta[i]);
        rod.frame[i] = before * joint;
        x += rod.elementLength * rod.frame[i].col(2);
        before = rod.frame[i];
    }
}

double referenceChain(DiscreteRod& rod, int iterations, double relaxation)
{
    const int n = rod.numNodes();
    double largest = 0.0;
    for (int it = 0; it < iterations; ++it) {
        largest = 0.0;
        Eigen::Vector3d f = Eigen::Vector3d::Zero();
        Eigen::Vector3d m = rod.torque[static_cast<size_t>(n - 1)];
        for (int k = n - 1; k >= 0; --k) {
            const auto i = static_cast<size_t>(k);
            if (k < n - 1) {
                m += (rod.elementLength * rod.frame[i].col(2)).cross(f);  // x_{i+1} - x_i by eq 7
            }
            // w (C^T m - K Theta - D (Theta - Theta_start)) / (K + D), as
            // (w / (K + D)) (C^T m + D Theta_start) - w Theta.
            const Eigen::Vector3d resistance = rod.jointStiffness(k) + rod.damping[i];
            const Eigen::Vector3d gain = (relaxation / resistance.array()).matrix();
            const Eigen::Vector3d pull = rod.damping[i].cwiseProduct(rod.thetaStart[i]);
            const Eigen::Vector3d net = rod.frame[i].transpose() * m + pull;
            const Eigen::Vector3d step = gain.cwiseProduct(net) - relaxation * rod.theta[i];
            rod.theta[i] += step;
            largest = std::max(largest, step.cwiseAbs().maxCoeff());
            f += rod.force[i];
            if (k > 0 && k < n - 1) {
                m += rod.torque[i];
            }
        }
        referenceRebuild(rod);
    }
    return largest;
}

// --- Bitwise comparison. ---

bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

template <typename Derived>
::testing::AssertionResult sameBits(const Eigen::MatrixBase<Derived>& a, const Eigen::MatrixBase<Derived>& b)
{
    for (Eigen::Index i = 0; i < a.size(); ++i) {
        if (!sameBits(a.reshaped()(i), b.reshaped()(i))) {
            return ::testing::AssertionFailure()
                   << "coefficient " << i << ": " << a.reshaped()(i) << " vs " << b.reshaped()(i);
        }
    }
    return ::testing::AssertionSuccess();
}

/// Positions, frames and Theta of every node, bit for bit; stops at the first difference.
::testing::AssertionResult sameRod(const DiscreteRod& a, const DiscreteRod& b)
{
    if (a.numNodes() != b.numNodes()) {
        return ::testing::AssertionFailure() << a.numNodes() << " nodes vs " << b.numNodes();
    }
    for (size_t i = 0; i < static_cast<size_t>(a.numNodes()); ++i) {
        for (const auto& result :
             {sameBits(a.position[i], b.position[i]), sameBits(a.theta[i], b.theta[i])}) {
            if (!result) {
                return ::testing::AssertionFailure() << "node " << i << ": " << result.message();
            }
        }
        if (const auto result = sameBits(a.frame[i], b.frame[i]); !result) {
            return ::testing::AssertionFailure() << "frame " << i << ": " << result.message();
        }
    }
    return ::testing::AssertionSuccess();
}

/// The benchmark's kind of load (bench/report/ScopeScene.h): weight, side
/// forces at every fifth node, an axial tip push, plus torques on an
/// interior node and the tip.
void applyLoads(Colonoscope& scope)
{
    scope.clearLoads();
    scope.addGravity(Eigen::Vector3d(0.0, 0.0, -9.81));
    const int n = scope.numInsertedNodes();
    for (int g = 5; g < n - 1; g += 5) {
        const double side = 0.05 + 0.15 * std::abs(std::sin(0.3 * g));
        scope.setNodeForce(g, scope.rod().force[static_cast<size_t>(g)] +
                                  Eigen::Vector3d(-0.02, side * std::cos(0.7 * g), side * std::sin(0.7 * g)));
    }
    scope.setNodeForce(n - 1, scope.rod().force.back() + Eigen::Vector3d(-0.3, 0.05, 0.0));
    scope.setNodeTorque(n / 2, Eigen::Vector3d(0.001, -0.002, 0.003));
    scope.setNodeTorque(n - 1, Eigen::Vector3d(0.0, 0.004, 0.01));
}

// Both branches of Rodrigues' coefficients (series below |theta| = 0.6,
// sin/cos above), on both sides of the switch and over the rod's range.
TEST(ChainSolverBits, RotationMatchesThePlainFormula)
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        Eigen::Vector3d axis(unit(random), unit(random), unit(random));
        const double angle =
            trial % 2 == 0 ? 1.2 * std::abs(unit(random)) : 0.6 * (1.0 + 1e-3 * unit(random));
        const Eigen::Vector3d theta = angle * axis.normalized();
        ASSERT_TRUE(sameBits(colonosim::scope::rotationFromVector(theta), referenceRotation(theta)))
            << "theta " << theta.transpose();
    }
}

// The benchmark's setting: 80-node scope inserted 1.2 m with the dials
// deflected and the shaft turned, 50 iterations a step, joint damping on;
// the reference continues from its own state every step.
TEST(ChainSolverBits, LoadedDampedDialledScopeMatchesThePlainChainOverTwoHundredSteps)
{
    // The step guard (ColonoscopeTest) would refuse the loads' first steps
    // at 60 Hz and solve them again with more damping than the reference has.
    ScopeParameters unguarded;
    unguarded.maxNodeStep = ScopeParameters::maxNodeStepSpec.maxValue;
    Colonoscope scope(unguarded);
    scope.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ());
    scope.setInsertion(1.2);
    scope.setDials(0.6, -0.2);
    scope.setShaftRotation(0.3);
    DiscreteRod reference = scope.rod();
    ASSERT_TRUE(sameRod(scope.rod(), reference));
    const int iterations = static_cast<int>(scope.parameters().solverIterations);
    for (int step = 0; step < 200; ++step) {
        scope.beginStep(1.0 / 60.0, step < 100 ? 1.0 : 0.0);  // damped, then quasi-static
        applyLoads(scope);
        reference.force = scope.rod().force;
        reference.torque = scope.rod().torque;
        reference.damping = scope.rod().damping;
        reference.thetaStart = reference.theta;
        scope.step();
        referenceChain(reference, iterations, scope.parameters().solverRelaxation);
        ASSERT_TRUE(sameRod(scope.rod(), reference)) << "step " << step;
    }
}

// The single-iteration form (contact updates between iterations) and the
// residual solveChain returns, on cantilevers of 1, 2 and 79 elements.
TEST(ChainSolverBits, CantileverIterationsAndResidualMatchThePlainChain)
{
    for (int elements : {1, 2, 79}) {
        for (double alpha : {0.5, 4.0}) {
            DiscreteRod rod = colonosim::scope::makeCantilever(elements, 1.0, 0.033, 0.44,
                                                               {.tipLoad = alpha * 0.033, .tipTorque = 0.01});
            DiscreteRod reference = rod;
            for (int iterations : {1, 1, 7, 50}) {
                const double residual = solveChain(rod, iterations, 0.5);
                EXPECT_TRUE(sameBits(residual, referenceChain(reference, iterations, 0.5)));
                ASSERT_TRUE(sameRod(rod, reference)) << elements << " elements, alpha " << alpha;
            }
        }
    }
}

}  // namespace
