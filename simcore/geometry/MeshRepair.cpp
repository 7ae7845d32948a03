#include "simcore/geometry/MeshRepair.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <unordered_map>

namespace colonosim::geometry {

namespace {

using Edge = std::pair<int, int>;
Edge undirected(int a, int b)
{
    return {std::min(a, b), std::max(a, b)};
}

[[noreturn]] void refuse(const std::string& label, const std::string& what)
{
    throw MeshImportError(label + ": " + what);
}

void checkFinite(const TriangleMesh& mesh, const std::string& label)
{
    for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i) {
        if (!mesh.vertices.col(i).allFinite()) {
            std::ostringstream s;
            s << "vertex " << i << " has a non-finite coordinate (" << mesh.vertices(0, i) << ", "
              << mesh.vertices(1, i) << ", " << mesh.vertices(2, i) << "; allowed: finite numbers)";
            refuse(label, s.str());
        }
    }
}

void mergeVertices(TriangleMesh& mesh, MeshRepairReport& report)
{
    const Eigen::Vector3d lo = mesh.vertices.rowwise().minCoeff();
    const Eigen::Vector3d hi = mesh.vertices.rowwise().maxCoeff();
    const double eps = std::max(1e-9 * (hi - lo).norm(), 1e-15);
    std::map<std::array<long long, 3>, int> seen;
    std::vector<int> remap(static_cast<std::size_t>(mesh.vertices.cols()));
    Eigen::Matrix3Xd kept(3, mesh.vertices.cols());
    int numKept = 0;
    for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i) {
        const std::array<long long, 3> key{std::llround(mesh.vertices(0, i) / eps),
                                           std::llround(mesh.vertices(1, i) / eps),
                                           std::llround(mesh.vertices(2, i) / eps)};
        const auto [it, inserted] = seen.try_emplace(key, numKept);
        if (inserted) {
            kept.col(numKept++) = mesh.vertices.col(i);
        }
        remap[static_cast<std::size_t>(i)] = it->second;
    }
    report.numMergedVertices = static_cast<int>(mesh.vertices.cols()) - numKept;
    mesh.vertices = kept.leftCols(numKept);
    for (auto& t : mesh.triangles) {
        for (int& k : t)
            k = remap[static_cast<std::size_t>(k)];
    }
}

void dropDegenerate(TriangleMesh& mesh, MeshRepairReport& report)
{
    const Eigen::Vector3d extent = mesh.vertices.rowwise().maxCoeff() - mesh.vertices.rowwise().minCoeff();
    const double minDoubleArea = 1e-14 * extent.squaredNorm();
    std::set<std::array<int, 3>> faces;
    std::vector<std::array<int, 3>> kept;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = mesh.vertices.col(t[0]);
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
            (mesh.vertices.col(t[1]) - a).cross(mesh.vertices.col(t[2]) - a).norm() <= minDoubleArea) {
            ++report.numDegenerateFacesRemoved;
            continue;
        }
        std::array<int, 3> key = t;
        std::sort(key.begin(), key.end());
        if (!faces.insert(key).second) {
            ++report.numDuplicateFacesRemoved;
            continue;
        }
        kept.push_back(t);
    }
    mesh.triangles = std::move(kept);
}

std::map<Edge, std::vector<int>> edgeFaces(const TriangleMesh& mesh)
{
    std::map<Edge, std::vector<int>> faces;
    for (int f = 0; f < mesh.numTriangles(); ++f) {
        const auto& t = mesh.triangles[static_cast<std::size_t>(f)];
        for (int k = 0; k < 3; ++k)
            faces[undirected(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)])]
                .push_back(f);
    }
    return faces;
}

bool hasDirectedEdge(const std::array<int, 3>& t, int a, int b)
{
    for (int k = 0; k < 3; ++k) {
        if (t[static_cast<std::size_t>(k)] == a && t[static_cast<std::size_t>((k + 1) % 3)] == b)
            return true;
    }
    return false;
}

/// Breadth-first orientation; also counts components.
void orient(TriangleMesh& mesh, const std::map<Edge, std::vector<int>>& faces, const std::string& label,
            MeshRepairReport& report)
{
    std::vector<std::vector<int>> neighbours(mesh.triangles.size());
    for (const auto& [edge, list] : faces) {
        if (list.size() == 2) {
            neighbours[static_cast<std::size_t>(list[0])].push_back(list[1]);
            neighbours[static_cast<std::size_t>(list[1])].push_back(list[0]);
        }
    }
    std::vector<char> visited(mesh.triangles.size(), 0);
    int numComponents = 0;
    for (std::size_t seed = 0; seed < mesh.triangles.size(); ++seed) {
        if (visited[seed])
            continue;
        ++numComponents;
        std::queue<int> queue;
        queue.push(static_cast<int>(seed));
        visited[seed] = 1;
        while (!queue.empty()) {
            const auto f = static_cast<std::size_t>(queue.front());
            queue.pop();
            const auto& t = mesh.triangles[f];
            for (int g : neighbours[f]) {
                auto& u = mesh.triangles[static_cast<std::size_t>(g)];
                // The shared edge must run the other way in the neighbour.
                int a = -1, b = -1;
                for (int k = 0; k < 3; ++k) {
                    const int p = t[static_cast<std::size_t>(k)],
                              q = t[static_cast<std::size_t>((k + 1) % 3)];
                    if (std::find(u.begin(), u.end(), p) != u.end() &&
                        std::find(u.begin(), u.end(), q) != u.end()) {
                        a = p;
                        b = q;
                    }
                }
                const bool consistent = hasDirectedEdge(u, b, a);
                if (visited[static_cast<std::size_t>(g)]) {
                    if (!consistent)
                        refuse(label, "non-orientable surface: faces " + std::to_string(f) + " and " +
                                          std::to_string(g) + " cannot agree (allowed: orientable)");
                    continue;
                }
                if (!consistent) {
                    std::swap(u[1], u[2]);
                    ++report.numFacesReoriented;
                }
                visited[static_cast<std::size_t>(g)] = 1;
                queue.push(g);
            }
        }
    }
    if (numComponents > 1) {
        refuse(label, std::to_string(numComponents) + " connected components (allowed: 1)");
    }
}

struct Loop {
    std::vector<int> vertices;  ///< in the direction the faces traverse them
    double perimeter = 0.0;
};

std::vector<Loop> boundaryLoops(const TriangleMesh& mesh, const std::map<Edge, std::vector<int>>& faces)
{
    std::unordered_map<int, int> next;  // directed boundary edge a -> b as in its face
    for (const auto& [edge, list] : faces) {
        if (list.size() != 1)
            continue;
        const auto& t = mesh.triangles[static_cast<std::size_t>(list[0])];
        const bool forward = hasDirectedEdge(t, edge.first, edge.second);
        next[forward ? edge.first : edge.second] = forward ? edge.second : edge.first;
    }
    std::vector<Loop> loops;
    std::set<int> used;
    for (const auto& [start, unused] : next) {
        if (used.contains(start))
            continue;
        Loop loop;
        int v = start;
        while (!used.contains(v) && next.contains(v)) {
            used.insert(v);
            loop.vertices.push_back(v);
            const int w = next.at(v);
            loop.perimeter += (mesh.vertices.col(w) - mesh.vertices.col(v)).norm();
            v = w;
        }
        loops.push_back(std::move(loop));
    }
    std::sort(loops.begin(), loops.end(),
              [](const Loop& a, const Loop& b) { return a.perimeter > b.perimeter; });
    return loops;
}

Eigen::Vector3d centroidOf(const TriangleMesh& mesh, const Loop& loop)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : loop.vertices)
        c += mesh.vertices.col(v);
    return c / static_cast<double>(loop.vertices.size());
}

/// Adds a fan closing `loop`; the fan traverses the loop edges backwards.
void appendFan(TriangleMesh& mesh, const Loop& loop, std::vector<std::array<int, 3>>& out,
               Eigen::Matrix3Xd& vertices)
{
    const int centre = static_cast<int>(vertices.cols());
    vertices.conservativeResize(3, centre + 1);
    vertices.col(centre) = centroidOf(mesh, loop);
    const auto n = loop.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back({loop.vertices[(i + 1) % n], loop.vertices[i], centre});
    }
}

}  // namespace

std::string MeshRepairReport::summary() const
{
    std::ostringstream s;
    s << numInputVertices << " vertices / " << numInputTriangles << " faces read; merged "
      << numMergedVertices << " duplicate vertices; dropped " << numDegenerateFacesRemoved
      << " degenerate and " << numDuplicateFacesRemoved << " duplicate faces; re-oriented "
      << numFacesReoriented << " faces" << (globallyFlipped ? "; flipped all faces" : "") << "; "
      << numOpenEnds << " open ends; filled " << numHolesFilled << " holes";
    return s.str();
}

MeshRepairReport repairTubeMesh(TriangleMesh& mesh, const std::string& label)
{
    MeshRepairReport report;
    report.numInputVertices = mesh.numVertices();
    report.numInputTriangles = mesh.numTriangles();
    if (mesh.numTriangles() == 0 || mesh.numVertices() < 3) {
        refuse(label, "empty mesh (" + std::to_string(mesh.numVertices()) + " vertices, " +
                          std::to_string(mesh.numTriangles()) + " faces; allowed: at least 1 face)");
    }
    for (const auto& t : mesh.triangles) {
        for (int k : t) {
            if (k < 0 || k >= mesh.numVertices())
                refuse(label, "face index " + std::to_string(k) + " out of range (allowed: 0.." +
                                  std::to_string(mesh.numVertices() - 1) + ")");
        }
    }
    checkFinite(mesh, label);
    mergeVertices(mesh, report);
    dropDegenerate(mesh, report);
    if (mesh.triangles.empty())
        refuse(label, "no non-degenerate face (allowed: at least 1)");

    auto faces = edgeFaces(mesh);
    int numNonManifold = 0;
    const std::pair<const Edge, std::vector<int>>* first = nullptr;
    for (const auto& entry : faces) {
        if (entry.second.size() > 2) {
            if (first == nullptr)
                first = &entry;
            ++numNonManifold;
        }
    }
    if (first != nullptr) {
        refuse(label, "non-manifold edge (vertices " + std::to_string(first->first.first) + ", " +
                          std::to_string(first->first.second) + ") shared by " +
                          std::to_string(first->second.size()) + " faces (allowed: at most 2); " +
                          std::to_string(numNonManifold) + " such edge(s)");
    }
    orient(mesh, faces, label, report);

    const std::vector<Loop> loops = boundaryLoops(mesh, faces);
    const double longest = loops.empty() ? 0.0 : loops.front().perimeter;
    std::vector<Loop> ends;
    Eigen::Matrix3Xd vertices = mesh.vertices;
    std::vector<std::array<int, 3>> triangles = mesh.triangles;
    for (const Loop& loop : loops) {
        if (ends.size() < 2 && loop.perimeter >= 0.5 * longest) {
            ends.push_back(loop);
        } else if (loop.perimeter < kMaxHoleFraction * longest) {
            appendFan(mesh, loop, triangles, vertices);
            ++report.numHolesFilled;
        } else {
            std::ostringstream s;
            s << "boundary loop of " << loop.vertices.size() << " edges and perimeter " << loop.perimeter
              << " is too large to fill (allowed: 2 open ends plus holes shorter than " << kMaxHoleFraction
              << " x " << longest << ")";
            refuse(label, s.str());
        }
    }
    mesh.vertices = vertices;
    mesh.triangles = triangles;
    report.numOpenEnds = static_cast<int>(ends.size());

    // Signed volume with the open ends virtually capped: positive when normals point out.
    std::vector<std::array<int, 3>> closed = mesh.triangles;
    Eigen::Matrix3Xd closedVertices = mesh.vertices;
    for (const Loop& end : ends)
        appendFan(mesh, end, closed, closedVertices);
    double volume = 0.0;
    for (const auto& t : closed) {
        volume +=
            closedVertices.col(t[0]).dot(closedVertices.col(t[1]).cross(closedVertices.col(t[2]))) / 6.0;
    }
    if (volume < 0.0) {
        for (auto& t : mesh.triangles)
            std::swap(t[1], t[2]);
        report.globallyFlipped = true;
    }
    return report;
}

}  // namespace colonosim::geometry
