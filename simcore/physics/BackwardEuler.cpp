#include "simcore/physics/BackwardEuler.h"

#include <cmath>

namespace colonosim::physics {

namespace {
void zeroOutside(const std::vector<std::uint8_t>& mask, Eigen::Matrix3Xd& m)
{
    for (Eigen::Index i = 0; i < m.cols(); ++i) {
        if (mask[static_cast<size_t>(i)] == 0) {
            m.col(i).setZero();
        }
    }
}

double dotMasked(const std::vector<int>& nodes, const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
    double sum = 0.0;
    for (const int i : nodes) {
        sum += a.col(i).dot(b.col(i));
    }
    return sum;
}
}  // namespace

void BackwardEuler::linearize(TissueBody& body, double h)
{
    m_frozen.clear();
    m_unfrozen.clear();
    for (const auto& term : body.forceTerms()) {
        if (term->hasSymmetricJacobian()) {
            (term->linearize(body.positions(), h) ? m_frozen : m_unfrozen).push_back(term.get());
        }
    }
}

void BackwardEuler::applySystem(const TissueBody& body, double h, const Eigen::Matrix3Xd& y,
                                Eigen::Matrix3Xd& out)
{
    // (h D + h^2 K+) y: the frozen terms in one pass each, the others as
    // separate stiffness and damping products at x.
    m_kTmp.setZero();
    for (const ForceTerm* term : m_frozen) {
        term->addSystemProduct(y, m_kTmp);
    }
    if (!m_unfrozen.empty()) {
        m_dTmp.setZero();
        for (const ForceTerm* term : m_unfrozen) {
            term->addDefiniteStiffnessProduct(body.positions(), y, m_dTmp);
        }
        m_kTmp += (h * h) * m_dTmp;
        m_dTmp.setZero();
        for (const ForceTerm* term : m_unfrozen) {
            term->addDampingProduct(body.positions(), y, m_dTmp);
        }
        m_kTmp += h * m_dTmp;
    }
    const Eigen::VectorXd& mass = body.masses();
    for (const int i : body.integratedNodes()) {
        out.col(i) = mass[i] * y.col(i) - m_kTmp.col(i);
    }
}

void BackwardEuler::step(TissueBody& body, double h)
{
    const Eigen::Index n = body.numNodes();
    for (Eigen::Matrix3Xd* m : {&m_f, &m_rhs, &m_dv, &m_r, &m_z, &m_p, &m_ap, &m_kTmp, &m_dTmp}) {
        if (m->cols() != n) {
            m->setZero(3, n);
        }
    }
    const std::vector<int>& nodes = body.integratedNodes();
    std::vector<std::uint8_t>& mask = m_mask;
    mask.assign(static_cast<size_t>(n), 0);
    for (const int i : nodes) {
        mask[static_cast<size_t>(i)] = 1;
    }
    Positions& x = body.positions();
    Velocities& v = body.velocities();

    body.computeForces(x, v, m_f);
    m_kTmp.setZero();
    m_p = v;
    zeroOutside(mask, m_p);
    body.stiffnessProduct(x, m_p, m_kTmp, true);
    for (const int i : nodes) {
        m_rhs.col(i) = h * (m_f.col(i) + h * m_kTmp.col(i));
    }

    body.stiffnessBounds(m_kRow, m_cRow);
    m_precond.resize(n);
    for (const int i : nodes) {
        // Diagonal of M - h D - h^2 K is about m + h c/2 + h^2 k/2 (half the Gershgorin row sum).
        m_precond[i] = 1.0 / (body.masses()[i] + 0.5 * h * m_cRow[i] + 0.5 * h * h * m_kRow[i]);
    }

    // Preconditioned conjugate gradients on the integrated nodes.
    linearize(body, h);
    zeroOutside(mask, m_dv);
    applySystem(body, h, m_dv, m_ap);
    for (const int i : nodes) {
        m_r.col(i) = m_rhs.col(i) - m_ap.col(i);
        m_z.col(i) = m_precond[i] * m_r.col(i);
    }
    m_p = m_z;
    zeroOutside(mask, m_p);
    const double rhsNorm = std::sqrt(dotMasked(nodes, m_rhs, m_rhs));
    double rz = dotMasked(nodes, m_r, m_z);
    int iteration = 0;
    double residual = std::sqrt(dotMasked(nodes, m_r, m_r));
    while (iteration < m_maxIterations && residual > m_tolerance * rhsNorm && rhsNorm > 0.0) {
        applySystem(body, h, m_p, m_ap);
        const double pAp = dotMasked(nodes, m_p, m_ap);
        if (!(pAp > 0.0)) {
            break;  // not positive definite along p: keep the current iterate
        }
        const double alpha = rz / pAp;
        for (const int i : nodes) {
            m_dv.col(i) += alpha * m_p.col(i);
            m_r.col(i) -= alpha * m_ap.col(i);
            m_z.col(i) = m_precond[i] * m_r.col(i);
        }
        const double rzNext = dotMasked(nodes, m_r, m_z);
        const double beta = rzNext / rz;
        rz = rzNext;
        for (const int i : nodes) {
            m_p.col(i) = m_z.col(i) + beta * m_p.col(i);
        }
        residual = std::sqrt(dotMasked(nodes, m_r, m_r));
        ++iteration;
    }
    m_lastIterations = iteration;
    m_lastResidual = rhsNorm > 0.0 ? residual / rhsNorm : 0.0;

    for (const int i : nodes) {
        v.col(i) += m_dv.col(i);
        x.col(i) += h * v.col(i);
    }
}

}  // namespace colonosim::physics
