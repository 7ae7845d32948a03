#include "simcore/geometry/TubeCentreline.h"

#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/geometry/CentrelineSampling.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>

namespace colonosim::geometry {

namespace {

using Adjacency = std::vector<std::vector<std::pair<int, double>>>;

std::vector<double> geodesic(const Adjacency& adj, const std::vector<int>& sources)
{
    std::vector<double> dist(adj.size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (int s : sources) {
        dist[static_cast<std::size_t>(s)] = 0.0;
        queue.push({0.0, s});
    }
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > dist[static_cast<std::size_t>(v)]) continue;
        for (const auto& [w, len] : adj[static_cast<std::size_t>(v)]) {
            if (d + len < dist[static_cast<std::size_t>(w)]) {
                dist[static_cast<std::size_t>(w)] = d + len;
                queue.push({d + len, w});
            }
        }
    }
    return dist;
}

/// Open boundary loops, longest first (vertex lists).
std::vector<std::vector<int>> boundaryLoops(const TriangleMesh& mesh)
{
    std::map<std::pair<int, int>, int> count;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::map<int, std::vector<int>> link;
    for (const auto& [e, n] : count) {
        if (n == 1) {
            link[e.first].push_back(e.second);
            link[e.second].push_back(e.first);
        }
    }
    std::vector<std::vector<int>> loops;
    std::set<int> used;
    for (const auto& [start, unused] : link) {
        if (used.contains(start)) continue;
        std::vector<int> loop;
        std::vector<int> stack{start};
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            if (!used.insert(v).second) continue;
            loop.push_back(v);
            for (int w : link[v]) stack.push_back(w);
        }
        loops.push_back(loop);
    }
    std::sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return loops;
}

Eigen::Vector3d centroid(const TriangleMesh& mesh, const std::vector<int>& vertices)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : vertices) c += mesh.vertices.col(v);
    return c / static_cast<double>(std::max<std::size_t>(1, vertices.size()));
}

/// Arc length of the nearest point of `p` on `polyline` (cumulative lengths `cum`).
double project(const std::vector<Eigen::Vector3d>& polyline, const std::vector<double>& cum, const Eigen::Vector3d& p, double* distance)
{
    double best = std::numeric_limits<double>::infinity();
    double bestS = 0.0;
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
        const Eigen::Vector3d d = polyline[i + 1] - polyline[i];
        const double len2 = d.squaredNorm();
        const double u = len2 > 0.0 ? std::clamp((p - polyline[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
        const double dist = (polyline[i] + u * d - p).squaredNorm();
        if (dist < best) {
            best = dist;
            bestS = cum[i] + u * std::sqrt(len2);
        }
    }
    if (distance != nullptr) *distance = std::sqrt(best);
    return bestS;
}

std::vector<double> cumulative(const std::vector<Eigen::Vector3d>& p)
{
    std::vector<double> c(p.size(), 0.0);
    for (std::size_t i = 1; i < p.size(); ++i) c[i] = c[i - 1] + (p[i] - p[i - 1]).norm();
    return c;
}

void smooth(std::vector<Eigen::Vector3d>& p, int iterations)
{
    for (int it = 0; it < iterations; ++it) {
        std::vector<Eigen::Vector3d> q = p;
        for (std::size_t i = 1; i + 1 < p.size(); ++i) q[i] = 0.25 * p[i - 1] + 0.5 * p[i] + 0.25 * p[i + 1];
        p = q;
    }
}

}  // namespace

Centreline computeCentreline(const TriangleMesh& mesh)
{
    const auto numV = static_cast<std::size_t>(mesh.numVertices());
    Adjacency adj(numV);
    double edgeSum = 0.0;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const int u = t[static_cast<std::size_t>(k)], v = t[static_cast<std::size_t>((k + 1) % 3)];
            const double len = (mesh.vertices.col(u) - mesh.vertices.col(v)).norm();
            adj[static_cast<std::size_t>(u)].push_back({v, len});
            adj[static_cast<std::size_t>(v)].push_back({u, len});
            edgeSum += len;
        }
    }
    const double meanEdge = edgeSum / std::max<std::size_t>(1, 3 * mesh.triangles.size());
    const auto loops = boundaryLoops(mesh);
    std::vector<int> sources;
    if (!loops.empty()) {
        sources = loops.front();
    } else {
        const auto d0 = geodesic(adj, {0});
        sources = {static_cast<int>(std::max_element(d0.begin(), d0.end()) - d0.begin())};
    }
    const std::vector<double> g = geodesic(adj, sources);

    // Bin by a parameter per vertex; returns slice centroids between the ends.
    const auto slicesBy = [&](const std::vector<double>& param, double total, int numSlices) {
        std::vector<Eigen::Vector3d> sum(static_cast<std::size_t>(numSlices), Eigen::Vector3d::Zero());
        std::vector<double> weight(static_cast<std::size_t>(numSlices), 0.0);
        for (std::size_t v = 0; v < numV; ++v) {
            if (!std::isfinite(param[v])) continue;
            const auto bin = static_cast<std::size_t>(std::clamp(static_cast<int>(param[v] / total * numSlices), 0, numSlices - 1));
            // Unweighted: on a bent tube an area-weighted centroid sits
            // kappa r^2 / 2 outside the axis (the outer wall is longer).
            sum[bin] += mesh.vertices.col(static_cast<Eigen::Index>(v));
            weight[bin] += 1.0;
        }
        std::vector<Eigen::Vector3d> polyline;
        if (!loops.empty()) polyline.push_back(centroid(mesh, loops[0]));
        for (std::size_t i = 0; i < sum.size(); ++i) {
            if (weight[i] > 0.0) polyline.push_back(sum[i] / weight[i]);
        }
        if (loops.size() > 1) polyline.push_back(centroid(mesh, loops[1]));
        return polyline;
    };
    double maxG = 0.0;
    for (double d : g) if (std::isfinite(d)) maxG = std::max(maxG, d);
    // Distance from the other end as well: u = g0 / (g0 + g1) has level sets
    // much closer to cross-sections than g0 alone, which lags on the inner
    // side of every bend.
    const std::vector<int> farEnd = loops.size() > 1
        ? loops[1]
        : std::vector<int>{static_cast<int>(std::max_element(g.begin(), g.end(), [](double a, double b) {
              return (std::isfinite(a) ? a : -1.0) < (std::isfinite(b) ? b : -1.0);
          }) - g.begin())};
    const std::vector<double> g1 = geodesic(adj, farEnd);
    std::vector<double> u(numV, 0.0);
    for (std::size_t v = 0; v < numV; ++v) {
        const double sum = g[v] + g1[v];
        u[v] = sum > 0.0 && std::isfinite(sum) ? maxG * g[v] / sum : 0.0;
    }
    const int numSlices = std::max(4, static_cast<int>(maxG / (2.0 * meanEdge)));
    std::vector<Eigen::Vector3d> polyline = slicesBy(u, maxG * (1.0 + 1e-9), numSlices);
    smooth(polyline, 3);

    std::vector<double> s(numV, 0.0);
    std::vector<double> axisDistance(numV, 0.0);
    for (int refinement = 0; refinement < 3; ++refinement) {
        const std::vector<double> cum = cumulative(polyline);
        for (std::size_t v = 0; v < numV; ++v) s[v] = project(polyline, cum, mesh.vertices.col(static_cast<Eigen::Index>(v)), &axisDistance[v]);
        const double length = cum.back();
        const std::vector<Eigen::Vector3d> ends{polyline.front(), polyline.back()};
        polyline = slicesBy(s, length * (1.0 + 1e-9), std::max(4, static_cast<int>(length / (2.0 * meanEdge))));
        if (loops.empty()) {
            polyline.insert(polyline.begin(), ends[0]);
            polyline.push_back(ends[1]);
        }
        smooth(polyline, 3);
    }

    Centreline c;
    const double length = cumulative(polyline).back();
    c.points = resampleByArcLength(polyline, std::max(2, static_cast<int>(std::ceil(length / 0.001)) + 1));
    computeArcLengthAndFrames(c, -Eigen::Vector3d::UnitY());

    // Radius: mean axis distance of the vertices projecting near each sample.
    const std::vector<double> cum = cumulative(c.points);
    std::vector<double> sum(c.points.size(), 0.0);
    std::vector<int> count(c.points.size(), 0);
    for (std::size_t v = 0; v < numV; ++v) {
        double dist = 0.0;
        const double sv = project(c.points, cum, mesh.vertices.col(static_cast<Eigen::Index>(v)), &dist);
        const auto i = static_cast<std::size_t>(std::clamp(static_cast<int>(std::lround(sv / length * (c.numPoints() - 1))), 0, c.numPoints() - 1));
        sum[i] += dist;
        ++count[i];
    }
    c.radius.assign(c.points.size(), 0.0);
    double last = 0.0;
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (count[i] > 0) last = sum[i] / count[i];
        c.radius[i] = last;
    }
    // Fill leading samples without vertices, then average over +-5 samples.
    for (std::size_t i = c.points.size(); i-- > 0;) {
        if (count[i] > 0) last = c.radius[i];
        else if (c.radius[i] == 0.0) c.radius[i] = last;
    }
    std::vector<double> r = c.radius;
    for (std::size_t i = 0; i < r.size(); ++i) {
        double acc = 0.0;
        int n = 0;
        for (std::size_t j = i >= 5 ? i - 5 : 0; j <= std::min(r.size() - 1, i + 5); ++j) { acc += c.radius[j]; ++n; }
        r[i] = acc / n;
    }
    c.radius = r;

    const AnatomyParameters defaults;
    c.segment.resize(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        double boundary = 0.0;
        int seg = 0;
        for (; seg + 1 < kNumSegments; ++seg) {
            boundary += defaults.length(static_cast<Segment>(seg)) / defaults.totalLength() * length;
            if (c.arcLength[i] < boundary) break;
        }
        c.segment[i] = static_cast<Segment>(seg);
    }
    return c;
}

}  // namespace colonosim::geometry
