#include "simcore/render/LaplaceChart.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace colonosim::render {

namespace {

struct Edge {
    int a = 0;
    int b = 0;
    double weight = 0.0;  ///< cotangent weight, summed over the edge's triangles
    int numTriangles = 0;
};

/// Undirected edges with their cotangent weights and triangle counts.
std::vector<Edge> cotangentEdges(const geometry::TriangleMesh& mesh)
{
    std::vector<Edge> halfEdges;
    halfEdges.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) {
        for (int c = 0; c < 3; ++c) {
            const int i = t[static_cast<size_t>(c)];
            const int j = t[static_cast<size_t>((c + 1) % 3)];
            const int k = t[static_cast<size_t>((c + 2) % 3)];
            const Eigen::Vector3d eij = mesh.vertices.col(j) - mesh.vertices.col(i);
            const Eigen::Vector3d eik = mesh.vertices.col(k) - mesh.vertices.col(i);
            const double area2 = eij.cross(eik).norm();
            const double cot = area2 > 0.0 ? eij.dot(eik) / area2 : 0.0;
            halfEdges.push_back({std::min(j, k), std::max(j, k), 0.5 * cot, 1});
        }
    }
    std::sort(halfEdges.begin(), halfEdges.end(),
              [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    std::vector<Edge> edges;
    for (const Edge& h : halfEdges) {
        if (!edges.empty() && edges.back().a == h.a && edges.back().b == h.b) {
            edges.back().weight += h.weight;
            ++edges.back().numTriangles;
        } else {
            edges.push_back(h);
        }
    }
    return edges;
}

/// Arc length of the point of the centreline nearest to x, continued along
/// the end tangents beyond either end, m.
double projectOnCentreline(const geometry::Centreline& c, const Eigen::Vector3d& x)
{
    double bestDistance = std::numeric_limits<double>::max();
    double bestS = 0.0;
    const int last = c.numPoints() - 1;
    for (int k = 0; k < last; ++k) {
        const Eigen::Vector3d& p = c.points[static_cast<size_t>(k)];
        const Eigen::Vector3d d = c.points[static_cast<size_t>(k + 1)] - p;
        const double length2 = d.squaredNorm();
        double t = length2 > 0.0 ? (x - p).dot(d) / length2 : 0.0;
        t = std::min(t, k + 1 == last ? std::numeric_limits<double>::max() : 1.0);
        t = std::max(t, k == 0 ? std::numeric_limits<double>::lowest() : 0.0);
        const double distance = (p + t * d - x).squaredNorm();
        if (distance < bestDistance) {
            bestDistance = distance;
            bestS = c.arcLength[static_cast<size_t>(k)] + t * std::sqrt(length2);
        }
    }
    return bestS;
}

}  // namespace

Eigen::VectorXd harmonicAlongCoordinate(const geometry::TriangleMesh& mesh,
                                        const geometry::Centreline& centreline)
{
    if (centreline.numPoints() < 2) {
        throw std::invalid_argument("centreline: needs at least two samples, has " +
                                    std::to_string(centreline.numPoints()));
    }
    if (mesh.numTriangles() == 0) {
        throw std::invalid_argument("mesh: has no triangles");
    }
    const int n = mesh.numVertices();
    const std::vector<Edge> edges = cotangentEdges(mesh);

    // Fixed values: -1 free, else u.
    Eigen::VectorXd fixed = Eigen::VectorXd::Constant(n, -1.0);
    const Eigen::Vector3d& start = centreline.points.front();
    const Eigen::Vector3d& end = centreline.points.back();
    int numStart = 0;
    int numEnd = 0;
    for (const Edge& e : edges) {
        if (e.numTriangles != 1) {
            continue;
        }
        for (const int v : {e.a, e.b}) {
            const bool nearStart =
                (mesh.vertices.col(v) - start).squaredNorm() < (mesh.vertices.col(v) - end).squaredNorm();
            if (fixed(v) < 0.0) {
                ++(nearStart ? numStart : numEnd);
            }
            fixed(v) = nearStart ? 0.0 : 1.0;
        }
    }
    if (numStart == 0) {
        throw std::invalid_argument("mesh: has no open end (boundary edge) near the centreline's start; the "
                                    "Laplace chart needs the anal ring open, u = 0 there");
    }
    if (numEnd == 0) {
        // The apex: furthest along the last tangent among the vertices within
        // two lumen radii of the centreline's end (elsewhere the colon may
        // reach further along that direction).
        const double reach = 2.0 * centreline.radius.back();
        int apex = -1;
        double furthest = std::numeric_limits<double>::lowest();
        for (int v = 0; v < n; ++v) {
            const Eigen::Vector3d offset = mesh.vertices.col(v) - end;
            const double along = offset.dot(centreline.tangents.back());
            if (offset.norm() < reach && along > furthest) {
                furthest = along;
                apex = v;
            }
        }
        if (apex < 0) {
            throw std::invalid_argument("mesh: has no vertex within " + std::to_string(reach) +
                                        " m (two lumen radii) of the centreline's end to hold u = 1");
        }
        fixed(apex) = 1.0;
    }

    std::vector<int> unknown(static_cast<size_t>(n), -1);
    int numUnknowns = 0;
    for (int v = 0; v < n; ++v) {
        if (fixed(v) < 0.0) {
            unknown[static_cast<size_t>(v)] = numUnknowns++;
        }
    }
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(edges.size() * 4 + static_cast<size_t>(numUnknowns));
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(numUnknowns);
    // A tiny diagonal keeps a vertex without positive weights determined (u = 0).
    for (int i = 0; i < numUnknowns; ++i) {
        entries.emplace_back(i, i, 1e-12);
    }
    for (const Edge& e : edges) {
        const double w = std::max(e.weight, 0.0);
        // Row of each free end: w (u_p - u_q), a fixed u_q moved to the right-hand side.
        for (const auto& [p, q] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
            const int ip = unknown[static_cast<size_t>(p)];
            const int iq = unknown[static_cast<size_t>(q)];
            if (ip < 0) {
                continue;
            }
            entries.emplace_back(ip, ip, w);
            if (iq >= 0) {
                entries.emplace_back(ip, iq, -w);
            } else {
                rhs(ip) += w * fixed(q);
            }
        }
    }
    Eigen::SparseMatrix<double> system(numUnknowns, numUnknowns);
    system.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success) {
        throw std::runtime_error("harmonicAlongCoordinate: the cotangent Laplacian could not be factorised");
    }
    const Eigen::VectorXd solution = solver.solve(rhs);
    Eigen::VectorXd u = fixed;
    for (int v = 0; v < n; ++v) {
        if (unknown[static_cast<size_t>(v)] >= 0) {
            u(v) = std::clamp(solution(unknown[static_cast<size_t>(v)]), 0.0, 1.0);
        }
    }
    return u;
}

std::vector<float> laplaceChart(const geometry::TriangleMesh& mesh, const geometry::Centreline& centreline)
{
    const Eigen::VectorXd u = harmonicAlongCoordinate(mesh, centreline);
    const int n = mesh.numVertices();
    int ringSize = 0;
    for (int v = 0; v < n; ++v) {
        ringSize += u(v) == 0.0 ? 1 : 0;
    }
    const int levelSize = std::max(8, 2 * ringSize);

    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&u](int x, int y) { return u(x) < u(y); });
    // Levels: the u = 0 set, groups of levelSize vertices in u order, the u = 1 set.
    std::vector<double> levelU;
    std::vector<Eigen::Vector3d> centroids;
    const auto addLevel = [&](double meanU, const Eigen::Vector3d& centroid) {
        levelU.push_back(meanU);
        centroids.push_back(centroid);
    };
    const auto centroidWhere = [&](double value) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        int count = 0;
        for (int v = 0; v < n; ++v) {
            if (u(v) == value) {
                sum += mesh.vertices.col(v);
                ++count;
            }
        }
        return Eigen::Vector3d(sum / std::max(count, 1));
    };
    addLevel(0.0, centroidWhere(0.0));
    for (int first = 0; first < n; first += levelSize) {
        const int count = std::min(levelSize, n - first);
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        double meanU = 0.0;
        for (int i = first; i < first + count; ++i) {
            centroid += mesh.vertices.col(order[static_cast<size_t>(i)]);
            meanU += u(order[static_cast<size_t>(i)]);
        }
        addLevel(meanU / count, centroid / count);
    }
    addLevel(1.0, centroidWhere(1.0));
    std::vector<double> levelS;
    for (const Eigen::Vector3d& centroid : centroids) {
        const double s = projectOnCentreline(centreline, centroid);
        levelS.push_back(levelS.empty() ? s : std::max(s, levelS.back()));
    }

    std::vector<float> chart(static_cast<size_t>(n) * 3);
    for (int v = 0; v < n; ++v) {
        const auto it = std::upper_bound(levelU.begin(), levelU.end(), u(v));
        const auto k = static_cast<size_t>(
            std::clamp(static_cast<int>(it - levelU.begin()) - 1, 0, static_cast<int>(levelU.size()) - 1));
        double s = levelS[k];
        if (k + 1 < levelU.size() && levelU[k + 1] > levelU[k]) {
            const double f = std::clamp((u(v) - levelU[k]) / (levelU[k + 1] - levelU[k]), 0.0, 1.0);
            s += f * (levelS[k + 1] - levelS[k]);
        }
        const geometry::CentrelineSample frame = geometry::sampleCentreline(centreline, s);
        const Eigen::Vector3d centre =
            frame.point + (s - std::clamp(s, 0.0, centreline.length())) * frame.tangent;
        const Eigen::Vector3d offset = mesh.vertices.col(v) - centre;
        const double theta = std::atan2(offset.dot(frame.binormal), offset.dot(frame.normal));
        const auto iv = static_cast<size_t>(v);
        chart[3 * iv] = static_cast<float>(s);
        chart[3 * iv + 1] = static_cast<float>(frame.radius * std::cos(theta));
        chart[3 * iv + 2] = static_cast<float>(frame.radius * std::sin(theta));
    }
    return chart;
}

}  // namespace colonosim::render
