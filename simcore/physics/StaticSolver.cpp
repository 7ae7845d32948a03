#include "simcore/physics/StaticSolver.h"
#include "simcore/physics/TangentPreconditioner.h"

#include <cmath>

namespace colonosim::physics {

namespace {
constexpr int kHalvings = 20;  ///< line-search halvings of a Newton step before it counts as no descent
/// An iteration that lowers the residual by less than this fraction makes no
/// headway: at that rate the 1e-5 N of the procedure's start would take
/// hundreds of iterations (the converging colons lower it by 20-40% an
/// iteration once linear, generated seeds 1-8 and the default colon).
constexpr double kHeadway = 0.01;
constexpr int kStagnantIterations = 3;  ///< iterations in a row without headway before the solve stops

double maxNodalForce(const TissueBody& body, const Forces& f)
{
    double largest = 0.0;
    for (const int i : body.integratedNodes()) {
        largest = std::max(largest, f.col(i).norm());
    }
    return largest;
}

/// Solves (-K+) dx = rhs on the integrated nodes by PCG, preconditioned by
/// `assembled` when given (else by the diagonal bound). Returns the
/// conjugate-gradient iterations taken.
int solveTangent(const TissueBody& body, const Forces& rhs, Eigen::Matrix3Xd& dx,
                 const TangentPreconditioner* assembled)
{
    const std::vector<int>& nodes = body.integratedNodes();
    Eigen::VectorXd kRow;
    Eigen::VectorXd cRow;
    if (assembled == nullptr) {
        body.stiffnessBounds(kRow, cRow);  // the diagonal bound
    }
    const auto apply = [&](const Eigen::Matrix3Xd& y, Eigen::Matrix3Xd& out) {
        Eigen::Matrix3Xd masked = Eigen::Matrix3Xd::Zero(3, y.cols());
        for (const int i : nodes) {
            masked.col(i) = y.col(i);
        }
        body.stiffnessProduct(body.positions(), masked, out, true);
        out = -out;
    };
    const auto dot = [&](const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
        double s = 0.0;
        for (const int i : nodes) {
            s += a.col(i).dot(b.col(i));
        }
        return s;
    };
    const auto precondition = [&](const Eigen::Matrix3Xd& residual, Eigen::Matrix3Xd& out) {
        if (assembled != nullptr) {
            assembled->apply(residual, out);
            return;
        }
        for (const int i : nodes) {
            out.col(i) = residual.col(i) / std::max(0.5 * kRow[i], 1e-12);
        }
    };
    dx.setZero(3, rhs.cols());
    Eigen::Matrix3Xd r = Eigen::Matrix3Xd::Zero(3, rhs.cols());
    Eigen::Matrix3Xd z = r;
    for (const int i : nodes) {
        r.col(i) = rhs.col(i);
    }
    precondition(r, z);
    Eigen::Matrix3Xd p = z;
    Eigen::Matrix3Xd ap;
    double rz = dot(r, z);
    const double rhsNorm = std::sqrt(dot(r, r));
    int it = 0;
    for (; it < 4 * static_cast<int>(3 * nodes.size()) && std::sqrt(dot(r, r)) > 1e-10 * rhsNorm; ++it) {
        apply(p, ap);
        const double pAp = dot(p, ap);
        if (!(pAp > 0.0)) {
            break;
        }
        const double alpha = rz / pAp;
        for (const int i : nodes) {
            dx.col(i) += alpha * p.col(i);
            r.col(i) -= alpha * ap.col(i);
        }
        precondition(r, z);
        const double rzNext = dot(r, z);
        for (const int i : nodes) {
            p.col(i) = z.col(i) + (rzNext / rz) * p.col(i);
        }
        rz = rzNext;
    }
    return it;
}
}  // namespace

StaticResult solveStaticEquilibrium(TissueBody& body, double forceTolerance, int maxIterations,
                                    StaticPreconditioner preconditioning)
{
    StaticResult result;
    body.velocities().setZero();
    Forces f;
    Eigen::Matrix3Xd dx;
    body.computeForces(body.positions(), body.velocities(), f);
    result.residual = maxNodalForce(body, f);
    // The tangent matrix assembled and factored at each iteration (its
    // colouring and ordering once): the conjugate gradients then converge
    // in one or two iterations. Factored once at the start, each later
    // iteration still took about 200 (the colon sags under gravity), and
    // the Jacobi preconditioner took about 1,900 (see TangentPreconditioner.h).
    TangentPreconditioner preconditioner;
    int stagnant = 0;
    while (result.iterations < maxIterations && result.residual > forceTolerance) {
        const bool assembled =
            preconditioning == StaticPreconditioner::Assembled && preconditioner.build(body);
        result.conjugateGradientIterations +=
            solveTangent(body, f, dx, assembled ? &preconditioner : nullptr);
        result.factoredIterations += assembled ? 1 : 0;
        const Positions start = body.positions();
        const double before = result.residual;
        double stepScale = 1.0;
        bool reduced = false;
        for (int halving = 0; halving < kHalvings && !reduced; ++halving) {
            body.positions() = start + stepScale * dx;
            body.computeForces(body.positions(), body.velocities(), f);
            const double trial = maxNodalForce(body, f);
            reduced = std::isfinite(trial) && trial < result.residual;
            if (reduced) {
                result.residual = trial;
            }
            stepScale *= 0.5;
        }
        ++result.iterations;
        if (!reduced) {
            // No step along dx lowers the largest force: the definite model
            // has run out of descent (a self-contact pressed by gravity left
            // 1.6 mN on a generated colon, and each further iteration cost
            // 0.3 s). Keep the best state and report the stall.
            body.positions() = start;
            result.stalled = true;
            break;
        }
        stagnant = result.residual > (1.0 - kHeadway) * before ? stagnant + 1 : 0;
        if (stagnant == kStagnantIterations) {
            // Descent, but in steps too short to reach the tolerance: the
            // definite model's direction no longer points at the
            // equilibrium (generated seed 7: a ring of the self-contact
            // pressed by gravity held 1.56 mN while 33 more iterations,
            // each halved 5-19 times, lowered it by 1e-8 N).
            result.stalled = true;
            break;
        }
    }
    result.converged = result.residual <= forceTolerance;
    return result;
}

}  // namespace colonosim::physics
