#include "simcore/procedure/ContactCoupling.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace colonosim::procedure {

namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return s;
}
}  // namespace

void ContactCoupling::reset()
{
    m_load.clear();
    m_normal.clear();
    m_triangle.clear();
    m_loads.resize(3, 0);
}

void ContactCoupling::align(int numNodes, int addedAtBase)
{
    const auto n = static_cast<size_t>(numNodes);
    std::vector<Eigen::Vector3d> load(n, Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero());
    std::vector<int> triangle(n, -1);
    for (int i = 0; i < numNodes; ++i) {
        const int old = i - addedAtBase;
        if (old >= 0 && old < static_cast<int>(m_load.size())) {
            load[static_cast<size_t>(i)] = m_load[static_cast<size_t>(old)];
            normal[static_cast<size_t>(i)] = m_normal[static_cast<size_t>(old)];
            triangle[static_cast<size_t>(i)] = m_triangle[static_cast<size_t>(old)];
        }
    }
    m_load.swap(load);
    m_normal.swap(normal);
    m_triangle.swap(triangle);
}

void ContactCoupling::buildCompliance(const scope::DiscreteRod& rod)
{
    const int n = rod.numNodes();
    const auto size = static_cast<size_t>(n) + 1;
    m_prefixA.assign(size, Eigen::Matrix3d::Zero());
    m_prefixB.assign(size, Eigen::Matrix3d::Zero());
    m_prefixC.assign(size, Eigen::Matrix3d::Zero());
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<size_t>(k);
        const Eigen::Matrix3d& frame = rod.frame[i];
        const Eigen::Matrix3d w =
            frame * rod.jointStiffness(k).cwiseInverse().asDiagonal() * frame.transpose();
        const Eigen::Matrix3d x = skew(rod.position[i]);
        m_prefixA[i + 1] = m_prefixA[i] + w;
        m_prefixB[i + 1] = m_prefixB[i] + w * x;
        m_prefixC[i + 1] = m_prefixC[i] + x.transpose() * w * x;
    }
    // G_ab = n_a^T C_ab n_b, C_ab = X_a^T A X_b - X_a^T B - B^T X_b + C from
    // the prefix sums up to joint min(a, b) - 1 (X = [x]x, X^T = -X).
    const auto m = static_cast<Eigen::Index>(m_active.size());
    m_delassus.resize(m, m);
    for (Eigen::Index a = 0; a < m; ++a) {
        const auto na = static_cast<size_t>(m_active[static_cast<size_t>(a)]);
        const Eigen::Vector3d& ua = m_normal[na];
        const Eigen::Vector3d pa = rod.position[na].cross(ua);  // X_a n_a
        for (Eigen::Index b = a; b < m; ++b) {
            const auto nb = static_cast<size_t>(m_active[static_cast<size_t>(b)]);
            const Eigen::Vector3d& ub = m_normal[nb];
            const Eigen::Vector3d pb = rod.position[nb].cross(ub);
            const size_t upto = std::min(na, nb);
            const double g = pa.dot(m_prefixA[upto] * pb) - pa.dot(m_prefixB[upto] * ub) -
                             ua.dot(m_prefixB[upto].transpose() * pb) + ua.dot(m_prefixC[upto] * ub);
            m_delassus(a, b) = g;
            m_delassus(b, a) = g;
        }
    }
}

void ContactCoupling::solveNormalForces()
{
    // (I + k_c G) delta = r - lambda_old, then lambda = max(0, lambda_old + delta):
    // nodes that would pull are fixed at zero and the rest re-solved (at most
    // a few rounds; the set only shrinks).
    const auto m = static_cast<Eigen::Index>(m_active.size());
    m_lambda = m_previous;
    std::vector<char> free(static_cast<size_t>(m), 1);
    for (int round = 0; round < 4 && m > 0; ++round) {
        std::vector<Eigen::Index> index;
        for (Eigen::Index a = 0; a < m; ++a) {
            if (free[static_cast<size_t>(a)] != 0) {
                index.push_back(a);
            }
        }
        const auto f = static_cast<Eigen::Index>(index.size());
        Eigen::VectorXd fixedDelta = Eigen::VectorXd::Zero(m);
        for (Eigen::Index a = 0; a < m; ++a) {
            if (free[static_cast<size_t>(a)] == 0) {
                fixedDelta[a] = -m_previous[a];
            }
        }
        const Eigen::VectorXd coupling = m_stiffness * (m_delassus * fixedDelta);
        Eigen::MatrixXd system(f, f);
        Eigen::VectorXd rhs(f);
        for (Eigen::Index r = 0; r < f; ++r) {
            for (Eigen::Index c = 0; c < f; ++c) {
                system(r, c) =
                    m_stiffness * m_delassus(index[static_cast<size_t>(r)], index[static_cast<size_t>(c)]);
            }
            system(r, r) += 1.0;
            const Eigen::Index a = index[static_cast<size_t>(r)];
            rhs[r] = m_raw[a] - m_previous[a] - coupling[a];
        }
        const Eigen::VectorXd delta = system.llt().solve(rhs);
        bool pulled = false;
        m_lambda = m_previous + fixedDelta;
        for (Eigen::Index r = 0; r < f; ++r) {
            const Eigen::Index a = index[static_cast<size_t>(r)];
            m_lambda[a] = m_previous[a] + delta[r];
            if (m_lambda[a] < 0.0) {
                free[static_cast<size_t>(a)] = 0;
                pulled = true;
            }
        }
        if (!pulled) {
            break;
        }
    }
    m_lambda = m_lambda.cwiseMax(0.0);
    // Trust region: the contact response of one loop step moves no node by
    // more than maxStep along its own normal (a contact-driven speed limit,
    // on the diagonal G_aa); the rest of the way is taken in later steps.
    for (Eigen::Index a = 0; a < m; ++a) {
        const double change = m_lambda[a] - m_previous[a];
        const double moved = m_delassus(a, a) * std::abs(change);
        if (moved > m_maxStep) {
            m_lambda[a] = m_previous[a] + change * (m_maxStep / moved);
        }
    }
}

void ContactCoupling::update(const contact::ContactResult& raw, const scope::DiscreteRod& rod,
                             int addedAtBase, const geometry::TriangleMesh& mesh,
                             const Eigen::Matrix3Xd& wall, double radius)
{
    const int n = rod.numNodes();
    align(n, addedAtBase);
    const auto size = static_cast<size_t>(n);
    std::vector<Eigen::Vector3d> rawNormal(size, Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> rawFriction(size, Eigen::Vector3d::Zero());
    std::vector<double> strongest(size, 0.0);
    for (const contact::ScopeContact& c : raw.contacts) {
        for (int end = 0; end < 2; ++end) {
            const int node = std::min(c.segment + end, n - 1);
            const double share = end == 0 ? 1.0 - c.segmentParam : c.segmentParam;
            if (node < 0 || share <= 0.0) {
                continue;
            }
            const auto i = static_cast<size_t>(node);
            rawNormal[i] += share * c.normalForce * c.normal;
            rawFriction[i] += share * c.frictionForce;
            if (share * c.normalForce > strongest[i]) {
                strongest[i] = share * c.normalForce;
                m_triangle[i] = c.triangle;
            }
        }
    }
    m_active.clear();
    std::vector<double> rawValue;
    for (int node = 0; node < n; ++node) {
        const auto i = static_cast<size_t>(node);
        const double magnitude = rawNormal[i].norm();
        if (magnitude > 0.0) {
            m_normal[i] = rawNormal[i] / magnitude;
            m_active.push_back(node);
            rawValue.push_back(magnitude);
        } else if (m_load[i].squaredNorm() > 0.0 && m_triangle[i] >= 0) {
            // Released? The narrow phase found no contact, so the depth is at
            // most zero; the signed gap to the last triangle's plane says how far.
            const auto& tri = mesh.triangles[static_cast<size_t>(m_triangle[i])];
            const Eigen::Vector3d a = wall.col(tri[0]);
            Eigen::Vector3d planeNormal = (wall.col(tri[1]) - a).cross(wall.col(tri[2]) - a);
            const double norm = planeNormal.norm();
            planeNormal = norm > 0.0 ? Eigen::Vector3d(planeNormal / norm) : m_normal[i];
            if (planeNormal.dot(m_normal[i]) < 0.0) {
                planeNormal = -planeNormal;
            }
            m_normal[i] = planeNormal;
            m_active.push_back(node);
            rawValue.push_back(
                std::min(0.0, m_stiffness * (radius - (rod.position[i] - a).dot(planeNormal))));
        }
    }
    const auto m = static_cast<Eigen::Index>(m_active.size());
    m_raw = Eigen::Map<const Eigen::VectorXd>(rawValue.data(), m);
    m_previous.resize(m);
    for (Eigen::Index a = 0; a < m; ++a) {
        const auto i = static_cast<size_t>(m_active[static_cast<size_t>(a)]);
        m_previous[a] = std::max(0.0, m_load[i].dot(m_normal[i]));
    }
    for (Eigen::Vector3d& load : m_load) {
        load.setZero();
    }
    buildCompliance(rod);
    solveNormalForces();

    m_compliance.assign(size, 0.0);
    m_deflection.assign(size, 0.0);
    m_loads.setZero(3, n);
    for (Eigen::Index a = 0; a < m; ++a) {
        const auto i = static_cast<size_t>(m_active[static_cast<size_t>(a)]);
        m_compliance[i] = m_delassus(a, a);
        m_deflection[i] = m_delassus.row(a).dot(m_lambda);
        m_load[i] = m_lambda[a] * m_normal[i];
        Eigen::Vector3d load = m_load[i];
        if (m_raw[a] > 0.0) {
            load += rawFriction[i] * (m_lambda[a] / m_raw[a]);  // |f_t| <= mu lambda
        }
        m_loads.col(static_cast<Eigen::Index>(i)) = load;
    }
    m_wallPoints.clear();
    for (const contact::ScopeContact& c : raw.contacts) {
        const auto s0 = static_cast<size_t>(c.segment);
        const auto s1 = static_cast<size_t>(std::min(c.segment + 1, n - 1));
        const double t = c.segmentParam;
        const double compliance = (1.0 - t) * m_compliance[s0] + t * m_compliance[s1];
        contact::WallContactPoint p;
        p.axisPoint = (1.0 - t) * rod.position[s0] + t * rod.position[s1];
        p.stiffness = m_stiffness / (1.0 + m_stiffness * compliance);
        p.depthOffset = std::max(0.0, (1.0 - t) * m_deflection[s0] + t * m_deflection[s1]);
        const double wallNormal = p.stiffness * std::max(0.0, c.depth + p.depthOffset);
        p.frictionScale = c.normalForce > 0.0 ? std::min(1.0, wallNormal / c.normalForce) : 0.0;
        m_wallPoints.push_back(p);
    }
}

}  // namespace colonosim::procedure
