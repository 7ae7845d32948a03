#include "simcore/scope/ReferenceSolver.h"

#include "simcore/scope/Rotation.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>

namespace colonosim::scope {

namespace {

using Frames = std::vector<Eigen::Matrix3d>;

/// Exact energy gradient (see the header) for frames `c` with loads scaled by `scale`.
Eigen::VectorXd gradient(const DiscreteRod& rod, const Frames& c, double scale)
{
    const int n = rod.numNodes();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * n);
    const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d downstream = Eigen::Vector3d::Zero();
    for (int k = n - 1; k >= 0; --k) {
        const auto i = static_cast<size_t>(k);
        const Eigen::Matrix3d& before = k == 0 ? rod.baseFrame : c[i - 1];
        const Eigen::Matrix3d q = before.transpose() * c[i];
        const Eigen::Vector3d theta = vectorFromRotation(rod.dial[i].transpose() * q);
        const Eigen::Vector3d moment =
            inverseRightJacobian(theta).transpose() * rod.jointStiffness(k).cwiseProduct(theta);
        g.segment<3>(3 * k) += moment;
        if (k > 0) {
            g.segment<3>(3 * (k - 1)) -= q * moment;
        }
        if (k < n - 1) {
            g.segment<3>(3 * k) -= rod.elementLength * e3.cross(c[i].transpose() * downstream);
        }
        if (k == n - 1 || (k > 0 && k < n - 1)) {
            // Torque at the tip acts on the tip frame; at interior node k on element k - 1.
            const size_t target = k == n - 1 ? i : i - 1;
            g.segment<3>(3 * static_cast<Eigen::Index>(target)) -=
                scale * c[target].transpose() * rod.torque[i];
        }
        downstream += scale * rod.force[i];
    }
    return g;
}

void applyIncrement(Frames& c, const Eigen::VectorXd& delta, double factor)
{
    for (size_t i = 0; i < c.size(); ++i) {
        c[i] = c[i] * rotationFromVector(factor * delta.segment<3>(3 * static_cast<Eigen::Index>(i)));
    }
}

Eigen::SparseMatrix<double> hessian(const DiscreteRod& rod, const Frames& c, double scale)
{
    const int n = rod.numNodes();
    const double h = 1e-6;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<size_t>(27 * n));
    Frames plus = c;
    Frames minus = c;
    for (int colour = 0; colour < 3; ++colour) {
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(axis);
            for (int k = colour; k < n; k += 3) {
                const auto i = static_cast<size_t>(k);
                plus[i] = c[i] * rotationFromVector(e);
                minus[i] = c[i] * rotationFromVector(-e);
            }
            const Eigen::VectorXd diff =
                (gradient(rod, plus, scale) - gradient(rod, minus, scale)) / (2.0 * h);
            for (int k = colour; k < n; k += 3) {
                const auto i = static_cast<size_t>(k);
                plus[i] = c[i];
                minus[i] = c[i];
                for (int m = std::max(0, k - 1); m <= std::min(n - 1, k + 1); ++m) {
                    for (int r = 0; r < 3; ++r) {
                        entries.emplace_back(3 * m + r, 3 * k + axis, diff(3 * m + r));
                    }
                }
            }
        }
    }
    Eigen::SparseMatrix<double> matrix(3 * n, 3 * n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

}  // namespace

ReferenceResult solveReference(DiscreteRod& rod, const ReferenceOptions& options)
{
    ReferenceResult result;
    Frames c(rod.frame.begin(), rod.frame.end());
    for (int stepIndex = 1; stepIndex <= options.loadSteps; ++stepIndex) {
        const double scale = static_cast<double>(stepIndex) / options.loadSteps;
        Eigen::VectorXd g = gradient(rod, c, scale);
        result.converged = false;
        for (int it = 0; it < options.maxIterations; ++it) {
            result.gradientNorm = g.cwiseAbs().maxCoeff();
            if (result.gradientNorm < options.tolerance) {
                result.converged = true;
                break;
            }
            ++result.iterations;
            Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
            lu.compute(hessian(rod, c, scale));
            if (lu.info() != Eigen::Success) {
                break;
            }
            const Eigen::VectorXd delta = lu.solve(-g);
            // Backtracking on the largest gradient component.
            double factor = 1.0;
            Frames trial = c;
            for (int halving = 0; halving < 12; ++halving, factor *= 0.5) {
                trial = c;
                applyIncrement(trial, delta, factor);
                const Eigen::VectorXd gTrial = gradient(rod, trial, scale);
                if (gTrial.cwiseAbs().maxCoeff() < result.gradientNorm || halving == 11) {
                    g = gTrial;
                    break;
                }
            }
            c = trial;
        }
        if (!result.converged) {
            result.gradientNorm = g.cwiseAbs().maxCoeff();
            result.converged = result.gradientNorm < options.tolerance;
        }
    }
    for (int k = 0; k < rod.numNodes(); ++k) {
        const auto i = static_cast<size_t>(k);
        const Eigen::Matrix3d& before = k == 0 ? rod.baseFrame : c[i - 1];
        rod.theta[i] = vectorFromRotation(rod.dial[i].transpose() * before.transpose() * c[i]);
    }
    rod.rebuild();
    return result;
}

}  // namespace colonosim::scope
