#include "simcore/physics/StabilityBound.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace colonosim::physics {

StabilityEstimate estimateStability(const TissueBody& body)
{
    Eigen::VectorXd kRow;
    Eigen::VectorXd cRow;
    return estimateStability(body, kRow, cRow);
}

StabilityEstimate estimateStability(const TissueBody& body, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow)
{
    body.stiffnessBounds(kRow, cRow);
    StabilityEstimate estimate;
    double omega2 = 0.0;
    estimate.betaMin = std::numeric_limits<double>::infinity();
    // Every free node, asleep or not: a sleeping node can wake at any loop
    // step, and the plan must already be stable for it then.
    for (int i = 0; i < body.numNodes(); ++i) {
        if (body.isFixed(i)) {
            continue;
        }
        const double m = body.masses()[i];
        if (kRow[i] / m > omega2) {
            omega2 = kRow[i] / m;
            estimate.stiffestNode = i;
        }
        estimate.dampingRateMax = std::max(estimate.dampingRateMax, cRow[i] / m);
        if (kRow[i] > 0.0) {
            const double beta = cRow[i] / kRow[i];
            estimate.betaMin = std::min(estimate.betaMin, beta);
            estimate.betaMax = std::max(estimate.betaMax, beta);
        }
    }
    if (!std::isfinite(estimate.betaMin)) {
        estimate.betaMin = 0.0;
    }
    estimate.omegaMax = std::sqrt(omega2);
    return estimate;
}

double amplification(IntegratorKind kind, double omega, double c, double h)
{
    Eigen::Matrix2d J;
    J << 0.0, 1.0, -omega * omega, -c;
    const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
    Eigen::Matrix2d A = I;
    switch (kind) {
    case IntegratorKind::ExplicitEuler: A = I + h * J; break;
    case IntegratorKind::SymplecticEuler:
        A << 1.0 - h * h * omega * omega, h * (1.0 - h * c), -h * omega * omega, 1.0 - h * c;
        break;
    case IntegratorKind::RungeKutta4: {
        const Eigen::Matrix2d hJ = h * J;
        const Eigen::Matrix2d hJ2 = hJ * hJ;
        A = I + hJ + hJ2 / 2.0 + hJ2 * hJ / 6.0 + hJ2 * hJ2 / 24.0;
        break;
    }
    case IntegratorKind::BackwardEuler: A = (I - h * J).inverse(); break;
    }
    // Eigenvalues (a + d)/2 +- sqrt(((a - d)/2)^2 + bc): this discriminant
    // avoids the cancellation of tr^2/4 - det when A is close to I.
    const double mean = 0.5 * (A(0, 0) + A(1, 1));
    const double halfDiff = 0.5 * (A(0, 0) - A(1, 1));
    const double discriminant = halfDiff * halfDiff + A(0, 1) * A(1, 0);
    if (discriminant < 0.0) {
        return std::sqrt(std::abs(A.determinant()));  // complex pair, |lambda|^2 = det
    }
    const double root = std::sqrt(discriminant);
    return std::max(std::abs(mean + root), std::abs(mean - root));
}

namespace {
bool stableAt(IntegratorKind kind, const StabilityEstimate& e, double h)
{
    constexpr int kSamples = 400;
    constexpr double kSlack = 1e-10;
    for (int s = 0; s < kSamples; ++s) {
        const double omega = e.omegaMax * std::pow(1e-4, 1.0 - static_cast<double>(s) / (kSamples - 1));
        const double w2 = omega * omega;
        const double cLow = e.betaMin * w2;
        const double cHigh = std::min(e.betaMax * w2, e.dampingRateMax);
        for (const double c : {cLow, std::max(cLow, cHigh)}) {
            if (amplification(kind, omega, c, h) > 1.0 + kSlack) {
                return false;
            }
        }
    }
    return true;
}
}  // namespace

double maxStableStep(IntegratorKind kind, const StabilityEstimate& estimate)
{
    if (kind == IntegratorKind::BackwardEuler || estimate.omegaMax <= 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    double lo = 1e-9 / estimate.omegaMax;
    double hi = 10.0 / estimate.omegaMax;
    if (!stableAt(kind, estimate, lo)) {
        return 0.0;
    }
    for (int iteration = 0; iteration < 60; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (stableAt(kind, estimate, mid) ? lo : hi) = mid;
    }
    return lo;
}

double exactOmegaMax(const TissueBody& body)
{
    const std::vector<int>& nodes = body.integratedNodes();
    const auto n = static_cast<Eigen::Index>(nodes.size());
    if (n > 1500) {
        throw std::invalid_argument("exactOmegaMax: too many nodes for a dense eigenproblem");
    }
    Eigen::MatrixXd S(3 * n, 3 * n);
    Eigen::Matrix3Xd dx = Eigen::Matrix3Xd::Zero(3, body.numNodes());
    Eigen::Matrix3Xd df;
    for (Eigen::Index a = 0; a < n; ++a) {
        for (int d = 0; d < 3; ++d) {
            dx(d, nodes[static_cast<size_t>(a)]) = 1.0;
            body.stiffnessProduct(body.positions(), dx, df);
            dx(d, nodes[static_cast<size_t>(a)]) = 0.0;
            const double ma = body.masses()[nodes[static_cast<size_t>(a)]];
            for (Eigen::Index b = 0; b < n; ++b) {
                const int nb = nodes[static_cast<size_t>(b)];
                const double mb = body.masses()[nb];
                S.block<3, 1>(3 * b, 3 * a + d) = -df.col(nb) / std::sqrt(ma * mb);
            }
        }
    }
    const Eigen::MatrixXd symmetric = 0.5 * (S + S.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(symmetric, Eigen::EigenvaluesOnly);
    return std::sqrt(std::max(0.0, solver.eigenvalues().maxCoeff()));
}

TopMode powerIterationTopMode(const TissueBody& body, int iterations)
{
    const std::vector<int>& nodes = body.integratedNodes();
    const Eigen::VectorXd& mass = body.masses();
    std::mt19937 random(12345);
    std::normal_distribution<double> normal;
    Eigen::Matrix3Xd q = Eigen::Matrix3Xd::Zero(3, body.numNodes());
    for (const int i : nodes) {
        q.col(i) = Eigen::Vector3d(normal(random), normal(random), normal(random));
    }
    Eigen::Matrix3Xd y;
    Eigen::Matrix3Xd df;
    // M^-1/2 (-A) M^-1/2 q over the integrated nodes, A the stiffness K or the damping D.
    const auto apply = [&](bool damping) {
        y = Eigen::Matrix3Xd::Zero(3, body.numNodes());
        for (const int i : nodes) {
            y.col(i) = q.col(i) / std::sqrt(mass[i]);
        }
        if (damping) {
            body.dampingProduct(body.positions(), y, df);
        } else {
            body.stiffnessProduct(body.positions(), y, df);
        }
        Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, body.numNodes());
        for (const int i : nodes) {
            out.col(i) = -df.col(i) / std::sqrt(mass[i]);
        }
        return out;
    };
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
        q /= q.norm();
        Eigen::Matrix3Xd next = apply(false);
        lambda = (q.array() * next.array()).sum();
        q = next;
    }
    TopMode mode;
    mode.omega = std::sqrt(std::max(0.0, lambda));
    q /= q.norm();
    mode.dampingRate = (q.array() * apply(true).array()).sum();
    mode.dampingRatio = mode.omega > 0.0 ? mode.dampingRate / (2.0 * mode.omega) : 0.0;
    return mode;
}

double powerIterationOmegaMax(const TissueBody& body, int iterations)
{
    return powerIterationTopMode(body, iterations).omega;
}

}  // namespace colonosim::physics
