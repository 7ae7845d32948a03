#include "simcore/geometry/SurfaceGraph.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace colonosim::geometry::surface {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

EdgeGraph buildGraph(const TriangleMesh& mesh)
{
    const auto numV = static_cast<std::size_t>(mesh.numVertices());
    std::vector<std::pair<int, int>> halfEdges;
    halfEdges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        for (std::size_t k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            if (a != b)
                halfEdges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    EdgeGraph g;
    std::vector<std::pair<int, int>> edges;
    for (std::size_t i = 0; i < halfEdges.size();) {
        std::size_t j = i;
        while (j < halfEdges.size() && halfEdges[j] == halfEdges[i])
            ++j;
        edges.push_back(halfEdges[i]);
        if (j - i == 1)
            g.boundary.push_back(halfEdges[i]);
        i = j;
    }
    g.offset.assign(numV + 1, 0);
    for (const auto& [a, b] : edges) {
        ++g.offset[static_cast<std::size_t>(a) + 1];
        ++g.offset[static_cast<std::size_t>(b) + 1];
    }
    for (std::size_t v = 0; v < numV; ++v)
        g.offset[v + 1] += g.offset[v];
    g.neighbour.resize(2 * edges.size());
    g.length.resize(2 * edges.size());
    std::vector<int> fill(g.offset.begin(), g.offset.end() - 1);
    double sum = 0.0;
    for (const auto& [a, b] : edges) {
        const double len = (mesh.vertices.col(a) - mesh.vertices.col(b)).norm();
        sum += len;
        const auto ia = static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++);
        const auto ib = static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++);
        g.neighbour[ia] = b;
        g.length[ia] = len;
        g.neighbour[ib] = a;
        g.length[ib] = len;
    }
    g.meanEdge = edges.empty() ? 0.0 : sum / static_cast<double>(edges.size());
    return g;
}

/// Dijkstra over the edge graph from several sources: O(E log V).
std::vector<double> geodesic(const EdgeGraph& g, const std::vector<int>& sources)
{
    std::vector<double> dist(g.offset.size() - 1, kInf);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (int s : sources) {
        dist[static_cast<std::size_t>(s)] = 0.0;
        queue.push({0.0, s});
    }
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > dist[static_cast<std::size_t>(v)])
            continue;
        for (int e = g.offset[static_cast<std::size_t>(v)]; e < g.offset[static_cast<std::size_t>(v) + 1];
             ++e) {
            const auto w = static_cast<std::size_t>(g.neighbour[static_cast<std::size_t>(e)]);
            const double dw = d + g.length[static_cast<std::size_t>(e)];
            if (dw < dist[w]) {
                dist[w] = dw;
                queue.push({dw, static_cast<int>(w)});
            }
        }
    }
    return dist;
}

int argmaxFinite(const std::vector<double>& d)
{
    int best = 0;
    double value = -1.0;
    for (std::size_t v = 0; v < d.size(); ++v) {
        if (std::isfinite(d[v]) && d[v] > value) {
            value = d[v];
            best = static_cast<int>(v);
        }
    }
    return best;
}

/// Open boundary loops (connected sets of boundary edges), longest first.
std::vector<std::vector<int>> boundaryLoops(const EdgeGraph& g, std::size_t numV)
{
    std::vector<std::vector<int>> link(numV);
    for (const auto& [a, b] : g.boundary) {
        link[static_cast<std::size_t>(a)].push_back(b);
        link[static_cast<std::size_t>(b)].push_back(a);
    }
    std::vector<char> used(numV, 0);
    std::vector<std::vector<int>> loops;
    for (std::size_t start = 0; start < numV; ++start) {
        if (link[start].empty() || used[start] != 0)
            continue;
        std::vector<int> loop;
        std::vector<int> stack{static_cast<int>(start)};
        used[start] = 1;
        while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            loop.push_back(v);
            for (int w : link[static_cast<std::size_t>(v)]) {
                if (used[static_cast<std::size_t>(w)] == 0) {
                    used[static_cast<std::size_t>(w)] = 1;
                    stack.push_back(w);
                }
            }
        }
        loops.push_back(std::move(loop));
    }
    std::stable_sort(loops.begin(), loops.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return loops;
}

}  // namespace colonosim::geometry::surface
