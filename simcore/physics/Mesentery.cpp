#include "simcore/physics/Mesentery.h"
#include "simcore/physics/LargestStrain.h"

#include <cmath>
#include <stdexcept>

namespace colonosim::physics {

int Mesentery::add(int node, const Eigen::Vector3d& root, double restLength, const Law& law)
{
    if (node < 0 || !root.allFinite() || !(restLength > 0.0) || !(law.stiffness >= 0.0) ||
        !(law.damping >= 0.0) || !(law.stiffeningStrain > 0.0) || !(law.maxStrain > 0.0)) {
        throw std::invalid_argument("Mesentery::add: invalid tether");
    }
    m_node.push_back(node);
    m_root.push_back(root);
    m_rest.push_back(restLength);
    m_invRest2.push_back(1.0 / (restLength * restLength));
    m_law.push_back(law);
    m_awake.append(numTethers() - 1, node);
    return numTethers() - 1;
}

double Mesentery::tension(const Law& law, double restLength, double delta)
{
    if (delta <= 0.0) {
        return 0.0;
    }
    const double ds = law.stiffeningStrain * restLength;
    const double dmax = law.maxStrain * restLength;
    const auto cubic = [&](double d) { return law.stiffness * d * (1.0 + (d / ds) * (d / ds)); };
    if (delta <= dmax) {
        return cubic(delta);
    }
    return cubic(dmax) + tangentStiffness(law, restLength, dmax) * (delta - dmax);
}

double Mesentery::tangentStiffness(const Law& law, double restLength, double delta)
{
    if (delta <= 0.0) {
        return 0.0;
    }
    const double ds = law.stiffeningStrain * restLength;
    const double d = std::min(delta, law.maxStrain * restLength);
    return law.stiffness * (1.0 + 3.0 * (d / ds) * (d / ds));
}

double Mesentery::maxStrain(const Positions& x) const
{
    return largestTensileStrain(
        m_node.size(), m_stretch2,
        [&](size_t t) { return (x.col(m_node[t]) - m_root[t]).squaredNorm() * m_invRest2[t]; },
        [&](size_t t) { return ((x.col(m_node[t]) - m_root[t]).norm() - m_rest[t]) / m_rest[t]; });
}

void Mesentery::addForce(const Positions& x, Forces& f) const
{
    for (const int entry : m_awake.entries()) {
        const auto t = static_cast<size_t>(entry);
        const Eigen::Vector3d d = x.col(m_node[t]) - m_root[t];
        const double l = d.norm();
        const double T = tension(m_law[t], m_rest[t], l - m_rest[t]);
        if (T > 0.0) {
            f.col(m_node[t]) -= (T / l) * d;
        }
    }
}

void Mesentery::addDampingForce(const Positions& x, const Velocities& v, Forces& f) const
{
    for (const int entry : m_awake.entries()) {
        const auto t = static_cast<size_t>(entry);
        const Eigen::Vector3d d = x.col(m_node[t]) - m_root[t];
        const double l2 = d.squaredNorm();
        if (l2 > m_rest[t] * m_rest[t]) {
            f.col(m_node[t]) -= (m_law[t].damping * d.dot(v.col(m_node[t])) / l2) * d;
        }
    }
}

void Mesentery::addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                    Eigen::Matrix3Xd& df) const
{
    for (size_t t = 0; t < m_node.size(); ++t) {
        const Eigen::Vector3d d = x.col(m_node[t]) - m_root[t];
        const double l = d.norm();
        const double delta = l - m_rest[t];
        if (delta <= 0.0) {
            continue;
        }
        const Eigen::Vector3d u = d / l;
        const Eigen::Vector3d r = dx.col(m_node[t]);
        const double axial = u.dot(r);
        const double T = tension(m_law[t], m_rest[t], delta);
        const double Tp = tangentStiffness(m_law[t], m_rest[t], delta);
        df.col(m_node[t]) -= Tp * axial * u + (T / l) * (r - axial * u);
    }
}

void Mesentery::addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df) const
{
    for (size_t t = 0; t < m_node.size(); ++t) {
        const Eigen::Vector3d d = x.col(m_node[t]) - m_root[t];
        const double l2 = d.squaredNorm();
        if (l2 > m_rest[t] * m_rest[t]) {
            df.col(m_node[t]) -= (m_law[t].damping * d.dot(dv.col(m_node[t])) / l2) * d;
        }
    }
}

void Mesentery::addStiffnessBound(const Positions& /*x*/, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const
{
    for (size_t t = 0; t < m_node.size(); ++t) {
        kRow[m_node[t]] += tangentStiffness(m_law[t], m_rest[t], m_law[t].maxStrain * m_rest[t]);
        cRow[m_node[t]] += m_law[t].damping;
    }
}

double Mesentery::potentialEnergy(const Positions& x) const
{
    double energy = 0.0;
    for (size_t t = 0; t < m_node.size(); ++t) {
        const Law& law = m_law[t];
        const double L = m_rest[t];
        const double delta = (x.col(m_node[t]) - m_root[t]).norm() - L;
        if (delta <= 0.0) {
            continue;
        }
        const double ds = law.stiffeningStrain * L;
        const double dmax = law.maxStrain * L;
        const auto quartic = [&](double d) {
            return law.stiffness * (0.5 * d * d + 0.25 * d * d * d * d / (ds * ds));
        };
        if (delta <= dmax) {
            energy += quartic(delta);
        } else {
            const double over = delta - dmax;
            energy += quartic(dmax) + tension(law, L, dmax) * over +
                      0.5 * tangentStiffness(law, L, dmax) * over * over;
        }
    }
    return energy;
}

}  // namespace colonosim::physics
