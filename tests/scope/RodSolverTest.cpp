// Convergence of the discrete rod with the element count, the chain solver
// against the Newton reference at the paper's setting (80 nodes, 50
// iterations), and torsion.

#include "simcore/scope/Cantilever.h"
#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/ReferenceSolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using colonosim::scope::CantileverLoads;
using colonosim::scope::DiscreteRod;
using colonosim::scope::makeCantilever;
using colonosim::scope::solveChain;
using colonosim::scope::solveReference;

constexpr double kLength = 1.0;
constexpr double kEI = 0.033;
constexpr double kGJ = 0.44;

Eigen::Vector3d referenceTip(int elements, const CantileverLoads& loads)
{
    DiscreteRod rod = makeCantilever(elements, kLength, kEI, kGJ, loads);
    EXPECT_TRUE(solveReference(rod).converged);
    return rod.position.back();
}

// The midpoint-rule joints make positions second order: the error ratio
// between n and 2n elements is 4, i.e. an observed order log2(ratio) of 2.
// Asserted within [1.8, 2.2] on the exact arc (end moment, t = 1.5) and on
// the tip-loaded elastica (alpha = 2) against a 1280-element solution.
TEST(RodConvergence, PositionErrorIsSecondOrderInElementCount)
{
    const double t = 1.5;
    const Eigen::Vector3d arc(kLength * std::sin(t) / t, -kLength * (1.0 - std::cos(t)) / t, 0.0);
    const CantileverLoads moment{.endMoment = t * kEI / kLength};
    const CantileverLoads tipLoad{.tipLoad = 2.0 * kEI / (kLength * kLength)};
    const Eigen::Vector3d fine = referenceTip(1280, tipLoad);
    double previousArc = 0.0;
    double previousLoad = 0.0;
    for (int n : {10, 20, 40, 80, 160}) {
        const double arcError = (referenceTip(n, moment) - arc).norm();
        const double loadError = (referenceTip(n, tipLoad) - fine).norm();
        std::printf("n %4d  end-moment tip error %.3e m  alpha=2 tip error %.3e m\n", n, arcError, loadError);
        if (previousArc > 0.0) {
            EXPECT_NEAR(std::log2(previousArc / arcError), 2.0, 0.2) << "n=" << n;
            EXPECT_NEAR(std::log2(previousLoad / loadError), 2.0, 0.2) << "n=" << n;
        }
        previousArc = arcError;
        previousLoad = loadError;
    }
}

// At the paper's setting the chain solver (relaxation 0.5) must agree with
// the reference to well under the discretisation error (~1e-4 L at 80
// nodes); 1e-6 L leaves margin above the measured agreement.
TEST(ChainSolver, AgreesWithReferenceAtEightyNodesFiftyIterations)
{
    for (double alpha : {1.0, 2.0}) {
        const CantileverLoads loads{.tipLoad = alpha * kEI / (kLength * kLength)};
        DiscreteRod chain = makeCantilever(79, kLength, kEI, kGJ, loads);
        solveChain(chain, 50, 0.5);
        const double error = (chain.position.back() - referenceTip(79, loads)).norm();
        std::printf("alpha %.0f: chain (80 nodes, 50 iterations) vs reference tip distance %.3e m\n", alpha,
                    error);
        EXPECT_LT(error, 1e-6 * kLength) << "alpha=" << alpha;
    }
}

// Without relaxation (w = 1, the paper's eq 4 as written) the iteration does
// not settle at alpha = 4, where w = 0.5 converges (measured: 14 iterations to
// 1e-6 m): this documents why the scope under-relaxes.
TEST(ChainSolver, RelaxationIsNeededAtAlphaFour)
{
    const CantileverLoads loads{.tipLoad = 4.0 * kEI / (kLength * kLength)};
    const Eigen::Vector3d reference = referenceTip(79, loads);
    DiscreteRod unrelaxed = makeCantilever(79, kLength, kEI, kGJ, loads);
    solveChain(unrelaxed, 200, 1.0);
    EXPECT_GT((unrelaxed.position.back() - reference).norm(), 1e-2 * kLength);
    DiscreteRod relaxed = makeCantilever(79, kLength, kEI, kGJ, loads);
    solveChain(relaxed, 50, 0.5);
    EXPECT_LT((relaxed.position.back() - reference).norm(), 1e-6 * kLength);
}

// Torsion: a twist phi at the clamp with no tip torque turns the straight
// rod rigidly (every frame turned by phi); a tip torque T adds T L / GJ,
// spread uniformly along the rod (element 39 has turned by 39.5 of 79
// element lengths: the clamp joint is a half joint). Exact for the discrete rod (compliances
// sum to L / GJ), so 1e-9 rad.
TEST(RodTorsion, BaseTwistIsRigidAndTipTorqueTwistsByTLOverGJ)
{
    for (double phi : {0.0, 0.7}) {
        for (double torque : {0.0, 0.1}) {
            DiscreteRod rod = makeCantilever(79, kLength, kEI, kGJ, {.tipTorque = torque});
            const Eigen::Matrix3d clamp = rod.baseFrame;
            rod.baseFrame = clamp * Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
            rod.rebuild();
            solveChain(rod, 50, 0.5);
            const Eigen::Matrix3d relative = clamp.transpose() * rod.frame.back();
            const double twist = std::atan2(relative(1, 0), relative(0, 0));
            EXPECT_NEAR(twist, phi + torque * kLength / kGJ, 1e-9) << "phi=" << phi << " T=" << torque;
            EXPECT_NEAR(rod.position.back().y(), 0.0, 1e-12);
            const Eigen::Matrix3d mid = clamp.transpose() * rod.frame[39];
            EXPECT_NEAR(std::atan2(mid(1, 0), mid(0, 0)), phi + torque * 39.5 / 79.0 * kLength / kGJ, 1e-9);
        }
    }
}

}  // namespace
