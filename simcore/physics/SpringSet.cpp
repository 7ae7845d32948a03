#include "simcore/physics/SpringSet.h"
#include "simcore/physics/LargestStrain.h"

#include "simcore/physics/SpringKernel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace colonosim::physics {

int SpringSet::add(int i, int j, double restLength, double stiffness, double damping, SpringFamily family)
{
    if (i == j || i < 0 || j < 0) {
        throw std::invalid_argument("SpringSet::add: a spring needs two distinct nodes");
    }
    if (!(restLength >= 0.0) || !(stiffness >= 0.0) || !(damping >= 0.0) || !std::isfinite(restLength) ||
        !std::isfinite(stiffness) || !std::isfinite(damping)) {
        throw std::invalid_argument(
            "SpringSet::add: rest length, stiffness and damping must be finite and >= 0");
    }
    m_i.push_back(i);
    m_j.push_back(j);
    m_rest.push_back(restLength);
    m_k.push_back(stiffness);
    m_c.push_back(damping);
    m_family.push_back(family);
    m_strainStale = true;
    const int s = numSprings() - 1;
    const auto awake = [this](int node) {
        return m_awake.empty() || static_cast<size_t>(node) >= m_awake.size() ||
               m_awake[static_cast<size_t>(node)];
    };
    if (awake(i) || awake(j)) {
        m_active.push_back(s);
        m_packedSlot.push_back(static_cast<int>(m_packed.size()));
        m_packed.push_back(packed(static_cast<size_t>(s)));
        m_gatherStale = true;
    } else {
        m_packedSlot.push_back(-1);
    }
    return s;
}

void SpringSet::remove(int s)
{
    const auto last = static_cast<size_t>(numSprings() - 1);
    const auto slot = static_cast<size_t>(s);
    m_i[slot] = m_i[last];
    m_j[slot] = m_j[last];
    m_rest[slot] = m_rest[last];
    m_k[slot] = m_k[last];
    m_c[slot] = m_c[last];
    m_family[slot] = m_family[last];
    m_i.pop_back();
    m_j.pop_back();
    m_rest.pop_back();
    m_k.pop_back();
    m_c.pop_back();
    m_family.pop_back();
    m_strainStale = true;
    onActiveSetChanged(m_awake);
}

void SpringSet::setTransverseDamping(double ratio)
{
    if (!(ratio >= 0.0 && ratio <= 1.0)) {
        throw std::invalid_argument("SpringSet::setTransverseDamping: ratio = " + std::to_string(ratio) +
                                    " must lie in [0, 1]");
    }
    m_transverseDamping = ratio;
    repack();
}

Eigen::Vector3d SpringSet::dampingForce(double c, const Eigen::Vector3d& d, double l2,
                                        const Eigen::Vector3d& relativeVelocity) const
{
    // c [(1 - t) u u^T + t I] dv, u = d / l.
    return ((1.0 - m_transverseDamping) * c * d.dot(relativeVelocity) / l2) * d +
           (m_transverseDamping * c) * relativeVelocity;
}

void SpringSet::setStiffness(int s, double stiffness, double damping)
{
    const auto e = static_cast<size_t>(s);
    m_k[e] = stiffness;
    m_c[e] = damping;
    if (const int slot = m_packedSlot[e]; slot >= 0) {
        m_packed[static_cast<size_t>(slot)] = packed(e);
    }
}

PackedSpring SpringSet::packed(size_t e) const
{
    return {m_i[e],
            m_j[e],
            m_rest[e],
            m_k[e],
            (1.0 - m_transverseDamping) * m_c[e],
            m_transverseDamping * m_c[e]};
}

void SpringSet::repack()
{
    m_packed.clear();
    m_packed.reserve(m_active.size());
    m_packedSlot.assign(m_i.size(), -1);
    for (const int s : m_active) {
        m_packedSlot[static_cast<size_t>(s)] = static_cast<int>(m_packed.size());
        m_packed.push_back(packed(static_cast<size_t>(s)));
    }
    m_gatherStale = true;
}

double SpringSet::maxTensileStrain(const Positions& x, SpringFamily family) const
{
    if (m_strainStale || family != m_strainFamily) {
        m_strainSprings.clear();
        for (size_t e = 0; e < m_i.size(); ++e) {
            if (m_family[e] == family && m_rest[e] > 0.0) {
                m_strainSprings.push_back({m_i[e], m_j[e], m_rest[e], 1.0 / (m_rest[e] * m_rest[e])});
            }
        }
        m_strainFamily = family;
        m_strainStale = false;
    }
    return largestTensileStrain(
        m_strainSprings.size(), m_stretch2,
        [&](size_t e) {
            const StrainSpring& p = m_strainSprings[e];
            return (x.col(p.j) - x.col(p.i)).squaredNorm() * p.invRest2;
        },
        [&](size_t e) {
            const StrainSpring& p = m_strainSprings[e];
            return ((x.col(p.j) - x.col(p.i)).norm() - p.rest) / p.rest;
        });
}

void SpringSet::addForce(const Positions& x, Forces& f) const
{
    for (const int s : m_active) {
        const auto e = static_cast<size_t>(s);
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l = d.norm();
        if (l < kMinLength) {
            continue;
        }
        const Eigen::Vector3d fs = (m_k[e] * (l - m_rest[e]) / l) * d;
        f.col(m_i[e]) += fs;
        f.col(m_j[e]) -= fs;
    }
}

void SpringSet::addDampingForce(const Positions& x, const Velocities& v, Forces& f) const
{
    for (const int s : m_active) {
        const auto e = static_cast<size_t>(s);
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l2 = d.squaredNorm();
        if (l2 < kMinLength * kMinLength) {
            continue;
        }
        const Eigen::Vector3d fs = dampingForce(m_c[e], d, l2, v.col(m_j[e]) - v.col(m_i[e]));
        f.col(m_i[e]) += fs;
        f.col(m_j[e]) -= fs;
    }
}

void SpringSet::addForceAndDamping(const Positions& x, const Velocities& v, Forces& f) const
{
    if (m_gatherStale) {
        m_gather.build(m_packed);
        m_gatherStale = false;
    }
    addSpringForces(m_packed, m_gather, x.data(), v.data(), f.data());
}

void SpringSet::addCouplings(std::vector<std::pair<int, int>>& pairs) const
{
    for (size_t s = 0; s < m_i.size(); ++s) {
        pairs.emplace_back(m_i[s], m_j[s]);
    }
}

template <bool Definite>
void SpringSet::stiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df) const
{
    for (const int s : m_active) {
        const auto e = static_cast<size_t>(s);
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l = d.norm();
        if (l < kMinLength) {
            continue;
        }
        const Eigen::Vector3d u = d / l;
        const Eigen::Vector3d r = dx.col(m_j[e]) - dx.col(m_i[e]);
        const double axial = u.dot(r);
        double transverse = 1.0 - m_rest[e] / l;
        if constexpr (Definite) {
            transverse = std::max(transverse, 0.0);
        }
        // K_e r = k [(1 - L/l)(r - u u.r) + u u.r]
        const Eigen::Vector3d kr = m_k[e] * (transverse * (r - axial * u) + axial * u);
        df.col(m_i[e]) += kr;
        df.col(m_j[e]) -= kr;
    }
}

void SpringSet::addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                    Eigen::Matrix3Xd& df) const
{
    stiffnessProduct<false>(x, dx, df);
}

void SpringSet::addDefiniteStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                            Eigen::Matrix3Xd& df) const
{
    stiffnessProduct<true>(x, dx, df);
}

void SpringSet::addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv, Eigen::Matrix3Xd& df) const
{
    for (const int s : m_active) {
        const auto e = static_cast<size_t>(s);
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l2 = d.squaredNorm();
        if (l2 < kMinLength * kMinLength) {
            continue;
        }
        const Eigen::Vector3d dr = dampingForce(m_c[e], d, l2, dv.col(m_j[e]) - dv.col(m_i[e]));
        df.col(m_i[e]) += dr;
        df.col(m_j[e]) -= dr;
    }
}

bool SpringSet::linearize(const Positions& x, double h)
{
    // h D_e + h^2 K+_e = (h^2 k t + h c t_d) I + (h^2 k (1 - t) + h c (1 - t_d)) u u^T,
    // with the transverse factor t = max(1 - L/l, 0) of the definite
    // stiffness and t_d the transverse damping ratio.
    m_linear.resize(m_active.size());
    for (size_t a = 0; a < m_active.size(); ++a) {
        const auto e = static_cast<size_t>(m_active[a]);
        LinearBlock& block = m_linear[a];
        block.i = m_i[e];
        block.j = m_j[e];
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l = d.norm();
        if (l < kMinLength) {
            block = {m_i[e], m_j[e], 0.0, 0.0, 0.0, 0.0, 0.0};
            continue;
        }
        const Eigen::Vector3d u = d / l;
        const double transverse = std::max(1.0 - m_rest[e] / l, 0.0);
        block.ux = u.x();
        block.uy = u.y();
        block.uz = u.z();
        block.along = h * h * m_k[e] * transverse + h * m_c[e] * m_transverseDamping;
        block.across = h * h * m_k[e] * (1.0 - transverse) + h * m_c[e] * (1.0 - m_transverseDamping);
    }
    return true;
}

void SpringSet::addSystemProduct(const Eigen::Matrix3Xd& y, Eigen::Matrix3Xd& out) const
{
    for (const LinearBlock& block : m_linear) {
        const Eigen::Vector3d u(block.ux, block.uy, block.uz);
        const Eigen::Vector3d r = y.col(block.j) - y.col(block.i);
        const Eigen::Vector3d g = block.along * r + (block.across * u.dot(r)) * u;
        out.col(block.i) += g;
        out.col(block.j) -= g;
    }
}

void SpringSet::addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const
{
    // ||K_e|| = k max(1, |1 - L/l|) at the current length l. A spring
    // compressed to nearly zero length has an unbounded transverse term; the
    // factor is capped at kMaxTransverseFactor there, and the step check of
    // TissueSimulation catches what the cap misses.
    // |1 - L/l| > 1 only for l < L/2: a spring longer than 0.51 L has the factor 1
    // exactly (|1 - L/l| < 0.97 there, rounding aside), which the squared
    // length tells without the root; the others take the formula.
    constexpr double kMaxTransverseFactor = 10.0;
    constexpr double kPlainFactorSquared = 0.51 * 0.51;
    for (size_t e = 0; e < m_i.size(); ++e) {
        const Eigen::Vector3d d = x.col(m_j[e]) - x.col(m_i[e]);
        const double l2 = d.squaredNorm();
        double factor = 1.0;
        if (!(l2 > kPlainFactorSquared * m_rest[e] * m_rest[e])) {
            const double l = std::sqrt(l2);
            factor = l > kMinLength
                         ? std::min(std::max(1.0, std::abs(1.0 - m_rest[e] / l)), kMaxTransverseFactor)
                         : 1.0;
        }
        kRow[m_i[e]] += 2.0 * factor * m_k[e];
        kRow[m_j[e]] += 2.0 * factor * m_k[e];
        cRow[m_i[e]] += 2.0 * m_c[e];
        cRow[m_j[e]] += 2.0 * m_c[e];
    }
}

double SpringSet::potentialEnergy(const Positions& x) const
{
    double energy = 0.0;
    for (size_t e = 0; e < m_i.size(); ++e) {
        const double stretch = (x.col(m_j[e]) - x.col(m_i[e])).norm() - m_rest[e];
        energy += 0.5 * m_k[e] * stretch * stretch;
    }
    return energy;
}

void SpringSet::onActiveSetChanged(const std::vector<std::uint8_t>& awake)
{
    m_awake = awake;
    m_active.clear();
    m_active.reserve(m_i.size());
    for (size_t e = 0; e < m_i.size(); ++e) {
        const auto awakeNode = [&](int node) {
            return m_awake.empty() || static_cast<size_t>(node) >= m_awake.size() ||
                   m_awake[static_cast<size_t>(node)] != 0;
        };
        if (awakeNode(m_i[e]) || awakeNode(m_j[e])) {
            m_active.push_back(static_cast<int>(e));
        }
    }
    repack();
}

}  // namespace colonosim::physics
