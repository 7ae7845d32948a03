/// \file
/// Explicit Euler, symplectic Euler and RK4 (see Integrator.h).

#include "simcore/physics/ExplicitIntegrators.h"

namespace colonosim::physics {

namespace {
void sizeLike(Eigen::Matrix3Xd& m, const TissueBody& body)
{
    if (m.cols() != body.numNodes()) {
        m.setZero(3, body.numNodes());
    }
}
}  // namespace

void ExplicitEuler::step(TissueBody& body, double h)
{
    sizeLike(m_f, body);
    Positions& x = body.positions();
    Velocities& v = body.velocities();
    body.computeForces(x, v, m_f);
    const Eigen::VectorXd& invM = body.inverseMasses();
    for (const int i : body.integratedNodes()) {
        x.col(i) += h * v.col(i);
        v.col(i) += (h * invM[i]) * m_f.col(i);
    }
}

void SymplecticEuler::step(TissueBody& body, double h)
{
    sizeLike(m_f, body);
    Positions& x = body.positions();
    Velocities& v = body.velocities();
    body.computeIntegratedForces(x, v, m_f);  // it reads the integrated nodes' forces only
    const Eigen::VectorXd& invM = body.inverseMasses();
    for (const int i : body.integratedNodes()) {
        v.col(i) += (h * invM[i]) * m_f.col(i);
        x.col(i) += h * v.col(i);
    }
}

void RungeKutta4::step(TissueBody& body, double h)
{
    for (Eigen::Matrix3Xd* m : {&m_x0, &m_v0, &m_xs, &m_vs, &m_f, &m_dx, &m_dv}) {
        sizeLike(*m, body);
    }
    Positions& x = body.positions();
    Velocities& v = body.velocities();
    const Eigen::VectorXd& invM = body.inverseMasses();
    const std::vector<int>& nodes = body.integratedNodes();
    m_x0 = x;
    m_v0 = v;
    m_xs = x;
    m_vs = v;
    for (const int i : nodes) {
        m_dx.col(i).setZero();
        m_dv.col(i).setZero();
    }
    // Stage k: derivative at (xs, vs); weights 1/6, 2/6, 2/6, 1/6; the next
    // stage point is x0 + c h k with c = 1/2, 1/2, 1.
    constexpr double weight[4] = {1.0 / 6.0, 2.0 / 6.0, 2.0 / 6.0, 1.0 / 6.0};
    constexpr double next[3] = {0.5, 0.5, 1.0};
    for (int stage = 0; stage < 4; ++stage) {
        body.computeForces(m_xs, m_vs, m_f);
        for (const int i : nodes) {
            const Eigen::Vector3d kx = m_vs.col(i);
            const Eigen::Vector3d kv = invM[i] * m_f.col(i);
            m_dx.col(i) += weight[stage] * kx;
            m_dv.col(i) += weight[stage] * kv;
            if (stage < 3) {
                m_xs.col(i) = m_x0.col(i) + next[stage] * h * kx;
                m_vs.col(i) = m_v0.col(i) + next[stage] * h * kv;
            }
        }
    }
    for (const int i : nodes) {
        x.col(i) = m_x0.col(i) + h * m_dx.col(i);
        v.col(i) = m_v0.col(i) + h * m_dv.col(i);
    }
}

}  // namespace colonosim::physics
