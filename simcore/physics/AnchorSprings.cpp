#include "simcore/physics/AnchorSprings.h"

#include <cmath>
#include <stdexcept>

namespace colonosim::physics {

int AnchorSprings::add(int node, const Eigen::Vector3d& anchor, double stiffness, double damping)
{
    if (node < 0 || !anchor.allFinite() || !(stiffness >= 0.0) || !(damping >= 0.0) ||
        !std::isfinite(stiffness) || !std::isfinite(damping)) {
        throw std::invalid_argument("AnchorSprings::add: invalid node, anchor, stiffness or damping");
    }
    m_node.push_back(node);
    m_anchor.push_back(anchor);
    m_k.push_back(stiffness);
    m_c.push_back(damping);
    m_awake.append(numAnchors() - 1, node);
    return numAnchors() - 1;
}

void AnchorSprings::addForce(const Positions& x, Forces& f) const
{
    for (const int entry : m_awake.entries()) {
        const auto a = static_cast<size_t>(entry);
        f.col(m_node[a]) -= m_k[a] * (x.col(m_node[a]) - m_anchor[a]);
    }
}

void AnchorSprings::addDampingForce(const Positions& /*x*/, const Velocities& v, Forces& f) const
{
    for (const int entry : m_awake.entries()) {
        const auto a = static_cast<size_t>(entry);
        f.col(m_node[a]) -= m_c[a] * v.col(m_node[a]);
    }
}

void AnchorSprings::addStiffnessProduct(const Positions& /*x*/, const Eigen::Matrix3Xd& dx,
                                        Eigen::Matrix3Xd& df) const
{
    for (size_t a = 0; a < m_node.size(); ++a) {
        df.col(m_node[a]) -= m_k[a] * dx.col(m_node[a]);
    }
}

void AnchorSprings::addDampingProduct(const Positions& /*x*/, const Eigen::Matrix3Xd& dv,
                                      Eigen::Matrix3Xd& df) const
{
    for (size_t a = 0; a < m_node.size(); ++a) {
        df.col(m_node[a]) -= m_c[a] * dv.col(m_node[a]);
    }
}

void AnchorSprings::addStiffnessBound(const Positions& /*x*/, Eigen::VectorXd& kRow,
                                      Eigen::VectorXd& cRow) const
{
    for (size_t a = 0; a < m_node.size(); ++a) {
        kRow[m_node[a]] += m_k[a];
        cRow[m_node[a]] += m_c[a];
    }
}

double AnchorSprings::potentialEnergy(const Positions& x) const
{
    double energy = 0.0;
    for (size_t a = 0; a < m_node.size(); ++a) {
        energy += 0.5 * m_k[a] * (x.col(m_node[a]) - m_anchor[a]).squaredNorm();
    }
    return energy;
}

}  // namespace colonosim::physics
