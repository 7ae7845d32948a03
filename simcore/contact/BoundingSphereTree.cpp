#include "simcore/contact/BoundingSphereTree.h"

#include <algorithm>
#include <cmath>

namespace colonosim::contact {

double squaredDistancePointSegment(const Eigen::Vector3d& point, const Eigen::Vector3d& p0,
                                   const Eigen::Vector3d& p1)
{
    const Eigen::Vector3d d = p1 - p0;
    const double dd = d.squaredNorm();
    double t = dd > 0.0 ? (point - p0).dot(d) / dd : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (p0 + t * d - point).squaredNorm();
}

BoundingSphereTree::BoundingSphereTree(const Eigen::Matrix3Xd& positions,
                                       std::vector<std::array<int, 3>> triangles)
    : m_triangles(std::move(triangles)), m_leafOfTriangle(m_triangles.size(), -1)
{
    if (m_triangles.empty()) {
        return;
    }
    std::vector<Eigen::Vector3d> centroids(m_triangles.size());
    for (size_t t = 0; t < m_triangles.size(); ++t) {
        const auto& tri = m_triangles[t];
        centroids[t] = (positions.col(tri[0]) + positions.col(tri[1]) + positions.col(tri[2])) / 3.0;
    }
    std::vector<int> order(m_triangles.size());
    for (size_t t = 0; t < order.size(); ++t) {
        order[t] = static_cast<int>(t);
    }
    m_nodes.reserve(2 * m_triangles.size());
    build(order, 0, static_cast<int>(order.size()), centroids);
    refit(positions);
}

int BoundingSphereTree::build(std::vector<int>& order, int begin, int end,
                              const std::vector<Eigen::Vector3d>& centroids)
{
    const int index = static_cast<int>(m_nodes.size());
    m_nodes.emplace_back();
    if (end - begin == 1) {
        m_nodes[static_cast<size_t>(index)].triangle = order[static_cast<size_t>(begin)];
        m_leafOfTriangle[static_cast<size_t>(order[static_cast<size_t>(begin)])] = index;
        return index;
    }
    Eigen::Vector3d lo = centroids[static_cast<size_t>(order[static_cast<size_t>(begin)])];
    Eigen::Vector3d hi = lo;
    for (int i = begin; i < end; ++i) {
        lo = lo.cwiseMin(centroids[static_cast<size_t>(order[static_cast<size_t>(i)])]);
        hi = hi.cwiseMax(centroids[static_cast<size_t>(order[static_cast<size_t>(i)])]);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](int a, int b) {
        return centroids[static_cast<size_t>(a)][axis] < centroids[static_cast<size_t>(b)][axis];
    });
    const int left = build(order, begin, mid, centroids);
    const int right = build(order, mid, end, centroids);
    m_nodes[static_cast<size_t>(index)].left = left;
    m_nodes[static_cast<size_t>(index)].right = right;
    return index;
}

void BoundingSphereTree::fitLeaf(Node& leaf, const Eigen::Matrix3Xd& positions) const
{
    const auto& tri = m_triangles[static_cast<size_t>(leaf.triangle)];
    const Eigen::Vector3d a = positions.col(tri[0]);
    const Eigen::Vector3d b = positions.col(tri[1]);
    const Eigen::Vector3d c = positions.col(tri[2]);
    leaf.centre = (a + b + c) / 3.0;
    const double r2 = std::max(
        {(a - leaf.centre).squaredNorm(), (b - leaf.centre).squaredNorm(), (c - leaf.centre).squaredNorm()});
    leaf.radius = std::sqrt(r2);
}

void BoundingSphereTree::refit(const Eigen::Matrix3Xd& positions)
{
    // Children always follow their parent in m_nodes, so a reverse sweep is bottom-up.
    for (int i = numNodes() - 1; i >= 0; --i) {
        Node& n = m_nodes[static_cast<size_t>(i)];
        if (!n.enabled) {
            continue;
        }
        if (n.left < 0) {
            fitLeaf(n, positions);
            continue;
        }
        const Node& a = m_nodes[static_cast<size_t>(n.left)];
        const Node& b = m_nodes[static_cast<size_t>(n.right)];
        const Eigen::Vector3d d = b.centre - a.centre;
        const double dist = d.norm();
        if (dist + b.radius <= a.radius) {
            n.centre = a.centre;
            n.radius = a.radius;
        } else if (dist + a.radius <= b.radius) {
            n.centre = b.centre;
            n.radius = b.radius;
        } else {
            n.radius = 0.5 * (dist + a.radius + b.radius);
            n.centre = a.centre + d * ((n.radius - a.radius) / dist);
        }
    }
}

void BoundingSphereTree::setEnabledFromNodes(std::span<const std::uint8_t> awake)
{
    for (Node& n : m_nodes) {
        if (n.triangle >= 0) {
            const auto& tri = m_triangles[static_cast<size_t>(n.triangle)];
            n.enabled = (awake[static_cast<size_t>(tri[0])] | awake[static_cast<size_t>(tri[1])] |
                         awake[static_cast<size_t>(tri[2])]) != 0;
        }
    }
    propagateEnabled();
}

void BoundingSphereTree::setTriangleEnabled(int triangle, bool enabled)
{
    m_nodes[static_cast<size_t>(leafOf(triangle))].enabled = enabled ? 1 : 0;
}

void BoundingSphereTree::enableAll()
{
    for (Node& n : m_nodes) {
        n.enabled = 1;
    }
}

void BoundingSphereTree::propagateEnabled()
{
    for (int i = numNodes() - 1; i >= 0; --i) {
        Node& n = m_nodes[static_cast<size_t>(i)];
        if (n.left >= 0) {
            n.enabled =
                m_nodes[static_cast<size_t>(n.left)].enabled | m_nodes[static_cast<size_t>(n.right)].enabled;
        }
    }
}

int BoundingSphereTree::numEnabledTriangles() const
{
    return static_cast<int>(std::count_if(m_nodes.begin(), m_nodes.end(),
                                          [](const Node& n) { return n.triangle >= 0 && n.enabled; }));
}

int BoundingSphereTree::queryCapsule(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius,
                                     std::vector<int>& out, std::vector<int>* visited) const
{
    if (m_nodes.empty() || !m_nodes[0].enabled) {
        return 0;
    }
    // A median split keeps the depth near log2(triangles); 128 covers any mesh that fits in memory.
    std::array<int, 128> stack{};
    int top = 0;
    stack[static_cast<size_t>(top++)] = 0;
    int visits = 0;
    while (top > 0) {
        const int index = stack[static_cast<size_t>(--top)];
        const Node& n = m_nodes[static_cast<size_t>(index)];
        ++visits;
        if (visited != nullptr) {
            visited->push_back(index);
        }
        const double reach = n.radius + radius;
        if (squaredDistancePointSegment(n.centre, p0, p1) > reach * reach) {
            continue;
        }
        if (n.triangle >= 0) {
            out.push_back(n.triangle);
            continue;
        }
        if (m_nodes[static_cast<size_t>(n.left)].enabled) {
            stack[static_cast<size_t>(top++)] = n.left;
        }
        if (m_nodes[static_cast<size_t>(n.right)].enabled) {
            stack[static_cast<size_t>(top++)] = n.right;
        }
    }
    return visits;
}

}  // namespace colonosim::contact
