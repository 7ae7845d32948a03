/// \file
/// Spring and mass construction for a wall mesh (see ColonBody.h).

#include "simcore/physics/ColonBody.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace colonosim::physics {

namespace {
struct EdgeInfo {
    std::vector<int> triangles;
    std::vector<int> opposite;
};

double triangleArea(const geometry::TriangleMesh& mesh, int t)
{
    const auto& tri = mesh.triangles[static_cast<size_t>(t)];
    const Eigen::Vector3d x0 = mesh.vertices.col(tri[0]);
    return 0.5 * (mesh.vertices.col(tri[1]) - x0).cross(mesh.vertices.col(tri[2]) - x0).norm();
}

double longestEdge(const geometry::TriangleMesh& mesh, int t)
{
    const auto& tri = mesh.triangles[static_cast<size_t>(t)];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
        longest = std::max(longest, (mesh.vertices.col(tri[(k + 1) % 3]) - mesh.vertices.col(tri[k])).norm());
    }
    return longest;
}
/// E t A / l^2, capped at 4 E t: a sliver or degenerate triangle would
/// otherwise give an unbounded spring constant (a regular pair of triangles
/// on an edge gives about 0.9 E t).
double vanGelderStiffness(double et, double area, double length)
{
    constexpr double kCap = 4.0;
    if (length <= 0.0) {
        return 0.0;
    }
    return et * std::min(area / (length * length), kCap);
}
}  // namespace

Eigen::VectorXd wallNodeMasses(const geometry::TriangleMesh& mesh, const TissueParameters& tissue)
{
    // A node with no area (a degenerate neighbourhood) still gets a small mass
    // so that M stays invertible; 1 mg is ~0.4% of a default node.
    constexpr double kMinimumNodeMass = 1e-6;  // kg
    Eigen::VectorXd mass = Eigen::VectorXd::Zero(mesh.numVertices());
    for (int t = 0; t < mesh.numTriangles(); ++t) {
        const double share = tissue.wallDensity * tissue.wallThickness * triangleArea(mesh, t) / 3.0;
        for (const int node : mesh.triangles[static_cast<size_t>(t)]) {
            mass[node] += share;
        }
    }
    return mass.cwiseMax(kMinimumNodeMass);
}

void addWallSprings(const geometry::TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& axis,
                    const TissueParameters& tissue, const StiffnessCalibration& calibration,
                    SpringSet& springs)
{
    std::map<std::pair<int, int>, EdgeInfo> edges;
    for (int t = 0; t < mesh.numTriangles(); ++t) {
        const auto& tri = mesh.triangles[static_cast<size_t>(t)];
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k];
            const int b = tri[(k + 1) % 3];
            EdgeInfo& info = edges[{std::min(a, b), std::max(a, b)}];
            info.triangles.push_back(t);
            info.opposite.push_back(tri[(k + 2) % 3]);
        }
    }
    const double et = tissue.wallYoungModulus * tissue.wallThickness;
    const double beta = tissue.dampingTime;
    const double mixed = std::sqrt(calibration.axial * calibration.circumferential);
    const auto& x = mesh.vertices;
    for (const auto& [key, info] : edges) {
        const auto [a, b] = key;
        const Eigen::Vector3d d = x.col(b) - x.col(a);
        const double length = d.norm();
        double area = 0.0;
        bool diagonal = info.triangles.size() == 2;
        for (const int t : info.triangles) {
            area += triangleArea(mesh, t);
            diagonal = diagonal && length >= longestEdge(mesh, t) * (1.0 - 1e-9);
        }
        const double base = vanGelderStiffness(et, area, length);
        double k = 0.0;
        SpringFamily family = SpringFamily::Structural;
        if (diagonal) {
            family = SpringFamily::Shear;
            k = tissue.shearStiffnessRatio * mixed * base;
        } else {
            const Eigen::Vector3d localAxis =
                (axis[static_cast<size_t>(a)] + axis[static_cast<size_t>(b)]).normalized();
            const bool alongAxis = length > 0.0 && std::abs(localAxis.dot(d)) >= 0.5 * length;
            k = (alongAxis ? calibration.axial : calibration.circumferential) * base;
        }
        springs.add(a, b, length, k, beta * k, family);

        if (info.opposite.size() == 2 && info.opposite[0] != info.opposite[1]) {
            const int p = info.opposite[0];
            const int q = info.opposite[1];
            const double across = (x.col(q) - x.col(p)).norm();
            const double baseAcross = vanGelderStiffness(et, area, across);
            const double ratio = diagonal ? tissue.shearStiffnessRatio : tissue.bendingStiffnessRatio;
            const double kAcross = ratio * mixed * baseAcross;
            springs.add(p, q, across, kAcross, beta * kAcross,
                        diagonal ? SpringFamily::Shear : SpringFamily::Bending);
        }
    }
}

}  // namespace colonosim::physics
