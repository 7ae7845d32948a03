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

namespace {
/// Re-indexes per-node state after `added` nodes entered the rod at its base
/// (negative: left it), keeping the tip end: new[i] = old[i - added]. In
/// place, so a warm vector does not allocate.
template <class T>
void shiftToTip(std::vector<T>& v, int numNodes, int added, const T& empty)
{
    const int old = static_cast<int>(v.size());
    v.resize(static_cast<size_t>(std::max(old, numNodes)), empty);
    const auto at = [&](int i) -> T { return i >= 0 && i < old ? v[static_cast<size_t>(i)] : empty; };
    if (added > 0) {
        for (int i = numNodes - 1; i >= 0; --i) {
            v[static_cast<size_t>(i)] = at(i - added);  // reads below i: not yet overwritten
        }
    } else {
        for (int i = 0; i < numNodes; ++i) {
            v[static_cast<size_t>(i)] = at(i - added);  // reads at or above i
        }
    }
    v.resize(static_cast<size_t>(numNodes));
}
}  // namespace

void ContactCoupling::align(int numNodes, int addedAtBase)
{
    shiftToTip(m_load, numNodes, addedAtBase, Eigen::Vector3d::Zero().eval());
    shiftToTip(m_normal, numNodes, addedAtBase, Eigen::Vector3d::Zero().eval());
    shiftToTip(m_triangle, numNodes, addedAtBase, -1);
}

void ContactCoupling::reserve(int numNodes)
{
    if (m_delassus.rows() >= numNodes) {
        return;
    }
    // Grows to the longest inserted scope once; every later step reuses it.
    m_delassus.resize(numNodes, numNodes);
    m_system.resize(numNodes, numNodes);
    for (Eigen::VectorXd* v : {&m_raw, &m_previous, &m_lambda, &m_fixedDelta, &m_coupling, &m_rhs}) {
        v->resize(numNodes);
    }
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
    const auto g = m_delassus.topLeftCorner(m, m);
    auto lambda = m_lambda.head(m);
    const auto previous = m_previous.head(m);
    lambda = previous;
    m_free.assign(static_cast<size_t>(m), 1);
    for (int round = 0; round < 4 && m > 0; ++round) {
        m_freeIndex.clear();
        for (Eigen::Index a = 0; a < m; ++a) {
            if (m_free[static_cast<size_t>(a)] != 0) {
                m_freeIndex.push_back(a);
            }
        }
        const auto f = static_cast<Eigen::Index>(m_freeIndex.size());
        auto fixedDelta = m_fixedDelta.head(m);
        for (Eigen::Index a = 0; a < m; ++a) {
            fixedDelta[a] = m_free[static_cast<size_t>(a)] == 0 ? -previous[a] : 0.0;
        }
        auto coupling = m_coupling.head(m);
        coupling.noalias() = g * fixedDelta;
        coupling *= m_stiffness;
        auto rhs = m_rhs.head(f);
        for (Eigen::Index r = 0; r < f; ++r) {
            for (Eigen::Index c = 0; c < f; ++c) {
                m_system(r, c) =
                    m_stiffness * g(m_freeIndex[static_cast<size_t>(r)], m_freeIndex[static_cast<size_t>(c)]);
            }
            m_system(r, r) += 1.0;
            const Eigen::Index a = m_freeIndex[static_cast<size_t>(r)];
            rhs[r] = m_raw[a] - previous[a] - coupling[a];
        }
        Eigen::Ref<Eigen::MatrixXd> system = m_system.topLeftCorner(f, f);
        Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> factor(system);  // in place, no allocation
        factor.solveInPlace(rhs);                                // rhs is now delta
        bool pulled = false;
        lambda = previous + fixedDelta;
        for (Eigen::Index r = 0; r < f; ++r) {
            const Eigen::Index a = m_freeIndex[static_cast<size_t>(r)];
            lambda[a] = previous[a] + rhs[r];
            if (lambda[a] < 0.0) {
                m_free[static_cast<size_t>(a)] = 0;
                pulled = true;
            }
        }
        if (!pulled) {
            break;
        }
    }
    lambda = lambda.cwiseMax(0.0);
    // Trust region: the contact response of one loop step moves no node by
    // more than maxStep along its own normal (a contact-driven speed limit,
    // on the diagonal G_aa); the rest of the way is taken in later steps.
    for (Eigen::Index a = 0; a < m; ++a) {
        const double change = lambda[a] - previous[a];
        const double moved = g(a, a) * std::abs(change);
        if (moved > m_maxStep) {
            lambda[a] = previous[a] + change * (m_maxStep / moved);
        }
    }
}

void ContactCoupling::update(const contact::ContactResult& raw, const scope::DiscreteRod& rod,
                             int addedAtBase, const geometry::TriangleMesh& mesh,
                             const Eigen::Matrix3Xd& wall, double radius)
{
    const int n = rod.numNodes();
    align(n, addedAtBase);
    reserve(n);
    const auto size = static_cast<size_t>(n);
    std::vector<Eigen::Vector3d>& rawNormal = m_rawNormal;
    std::vector<Eigen::Vector3d>& rawFriction = m_rawFriction;
    std::vector<double>& strongest = m_strongest;
    rawNormal.assign(size, Eigen::Vector3d::Zero());
    rawFriction.assign(size, Eigen::Vector3d::Zero());
    strongest.assign(size, 0.0);
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
    for (int node = 0; node < n; ++node) {
        const auto i = static_cast<size_t>(node);
        const double magnitude = rawNormal[i].norm();
        if (magnitude > 0.0) {
            m_normal[i] = rawNormal[i] / magnitude;
            m_raw[static_cast<Eigen::Index>(m_active.size())] = magnitude;
            m_active.push_back(node);
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
            m_raw[static_cast<Eigen::Index>(m_active.size())] =
                std::min(0.0, m_stiffness * (radius - (rod.position[i] - a).dot(planeNormal)));
            m_active.push_back(node);
        }
    }
    const auto m = static_cast<Eigen::Index>(m_active.size());
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
        m_deflection[i] = m_delassus.row(a).head(m).dot(m_lambda.head(m));
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
