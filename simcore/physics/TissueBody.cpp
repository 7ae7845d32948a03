#include "simcore/physics/TissueBody.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace colonosim::physics {

TissueBody::TissueBody(const Positions& restPositions, const Eigen::VectorXd& masses)
    : m_x(restPositions), m_v(Velocities::Zero(3, restPositions.cols())), m_mass(masses),
      m_inverseMass(masses.cwiseInverse()), m_fixed(static_cast<size_t>(restPositions.cols()), 0),
      m_awake(static_cast<size_t>(restPositions.cols()), 1),
      m_held(static_cast<size_t>(restPositions.cols()), 0), m_external(Forces::Zero(3, restPositions.cols()))
{
    if (masses.size() != restPositions.cols()) {
        throw std::invalid_argument("TissueBody: one mass per node is required");
    }
    for (Eigen::Index i = 0; i < masses.size(); ++i) {
        if (!(masses[i] > 0.0)) {
            throw std::invalid_argument("TissueBody: node " + std::to_string(i) + " has a non-positive mass");
        }
    }
    rebuildIntegratedNodes();
}

int TissueBody::addNode(const Eigen::Vector3d& position, double mass)
{
    if (!(mass > 0.0)) {
        throw std::invalid_argument("TissueBody::addNode: mass must be positive");
    }
    const Eigen::Index n = m_x.cols();
    m_x.conservativeResize(3, n + 1);
    m_v.conservativeResize(3, n + 1);
    m_external.conservativeResize(3, n + 1);
    m_mass.conservativeResize(n + 1);
    m_inverseMass.conservativeResize(n + 1);
    m_x.col(n) = position;
    m_v.col(n).setZero();
    m_external.col(n).setZero();
    m_mass[n] = mass;
    m_inverseMass[n] = 1.0 / mass;
    m_fixed.push_back(0);
    m_awake.push_back(1);
    m_held.push_back(0);
    m_integrated.push_back(static_cast<int>(n));
    for (auto& term : m_terms) {
        term->onActiveSetChanged(m_awake);
        term->onMassesChanged(m_mass);
    }
    return static_cast<int>(n);
}

void TissueBody::setMass(int node, double mass)
{
    if (!(mass > 0.0)) {
        throw std::invalid_argument("TissueBody::setMass: mass must be positive");
    }
    m_mass[node] = mass;
    m_inverseMass[node] = 1.0 / mass;
    for (auto& term : m_terms) {
        term->onMassesChanged(m_mass);
    }
}

void TissueBody::setFixed(int node, bool fixed)
{
    m_fixed[static_cast<size_t>(node)] = fixed ? 1 : 0;
    if (fixed) {
        m_v.col(node).setZero();
    }
    rebuildIntegratedNodes();
}

void TissueBody::applyExternalForce(int node, const Eigen::Vector3d& force)
{
    m_external.col(node) += force;
    holdAwake(node);
}

void TissueBody::holdAwake(int node)
{
    m_held[static_cast<size_t>(node)] = 1;
    if (m_awake[static_cast<size_t>(node)] == 0) {
        m_awake[static_cast<size_t>(node)] = 1;
        applyAwake();
    }
}

void TissueBody::clearExternalForces()
{
    m_external.setZero();
    std::fill(m_held.begin(), m_held.end(), 0);
}

ForceTerm& TissueBody::addForceTerm(std::unique_ptr<ForceTerm> term)
{
    term->onActiveSetChanged(m_awake);
    term->onMassesChanged(m_mass);
    m_terms.push_back(std::move(term));
    return *m_terms.back();
}

void TissueBody::addConstraint(std::unique_ptr<Constraint> constraint)
{
    m_constraints.push_back(std::move(constraint));
}

void TissueBody::computeForces(const Positions& x, const Velocities& v, Forces& f) const
{
    f = m_external;
    for (const auto& term : m_terms) {
        term->addForceAndDamping(x, v, f);
    }
}

void TissueBody::computeIntegratedForces(const Positions& x, const Velocities& v, Forces& f) const
{
    for (const int i : m_integrated) {
        f.col(i) = m_external.col(i);
    }
    for (const auto& term : m_terms) {
        term->addForceAndDamping(x, v, f);
    }
}

void TissueBody::stiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df,
                                  bool definite) const
{
    df.setZero(3, dx.cols());
    for (const auto& term : m_terms) {
        if (!term->hasSymmetricJacobian()) {
            continue;
        }
        if (definite) {
            term->addDefiniteStiffnessProduct(x, dx, df);
        } else {
            term->addStiffnessProduct(x, dx, df);
        }
    }
}

void TissueBody::declaredStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                          Eigen::Matrix3Xd& df) const
{
    df.setZero(3, dx.cols());
    for (const auto& term : m_terms) {
        if (term->hasSymmetricJacobian() && term->couplingsDeclared()) {
            term->addDefiniteStiffnessProduct(x, dx, df);
        }
    }
}

void TissueBody::dampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df) const
{
    df.setZero(3, dv.cols());
    for (const auto& term : m_terms) {
        if (term->hasSymmetricJacobian()) {
            term->addDampingProduct(x, dv, df);
        }
    }
}

int TissueBody::projectConstraints(Positions& x, Velocities& v) const
{
    int corrected = 0;
    for (const auto& constraint : m_constraints) {
        corrected += constraint->project(m_integrated, x, v);
    }
    return corrected;
}

double TissueBody::kineticEnergy() const
{
    double energy = 0.0;
    for (Eigen::Index i = 0; i < m_x.cols(); ++i) {
        energy += 0.5 * m_mass[i] * m_v.col(i).squaredNorm();
    }
    return energy;
}

double TissueBody::potentialEnergy() const
{
    double energy = 0.0;
    for (const auto& term : m_terms) {
        energy += term->potentialEnergy(m_x);
    }
    return energy;
}

void TissueBody::setAwake(const std::vector<std::uint8_t>& awake)
{
    if (awake.size() != static_cast<size_t>(numNodes())) {
        throw std::invalid_argument("TissueBody::setAwake: one flag per node is required");
    }
    m_awake = awake;
    applyAwake();
}

void TissueBody::applyAwake()
{
    for (Eigen::Index i = 0; i < m_x.cols(); ++i) {
        if (m_awake[static_cast<size_t>(i)] == 0) {
            m_v.col(i).setZero();
        }
    }
    rebuildIntegratedNodes();
    for (auto& term : m_terms) {
        term->onActiveSetChanged(m_awake);
    }
}

void TissueBody::stiffnessBounds(Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const
{
    kRow.setZero(numNodes());
    cRow.setZero(numNodes());
    for (const auto& term : m_terms) {
        term->addStiffnessBound(m_x, kRow, cRow);
    }
}

void TissueBody::rebuildIntegratedNodes()
{
    m_integrated.clear();
    for (int i = 0; i < numNodes(); ++i) {
        if (m_fixed[static_cast<size_t>(i)] == 0 && m_awake[static_cast<size_t>(i)] != 0) {
            m_integrated.push_back(i);
        }
    }
}

}  // namespace colonosim::physics
