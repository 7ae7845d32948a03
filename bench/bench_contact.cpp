// Times one contact step (refit + query + narrow phase + forces) of an
// 80-node scope polyline against the default procedural colon (1,905 nodes,
// 3,792 triangles). The scope lies along the centreline over the first
// metre, swinging sideways so that it touches the wall in places; the wall
// moves a little each iteration so that the refit works on new positions.
// Target: well under 100 us per step (the whole procedure step is 100-200 us).

#include "simcore/contact/ScopeWallContact.h"
#include "simcore/geometry/ProceduralColon.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

using namespace colonosim;

constexpr double kRadius = 6.5e-3;  ///< scope radius, m
constexpr int kScopeNodes = 80;
constexpr double kScopeLength = 1.0;  ///< m

/// Point, normal and radius of the centreline at arc length s (linear interpolation).
Eigen::Matrix3Xd scopeAlongCentreline(const geometry::Centreline& c)
{
    Eigen::Matrix3Xd x(3, kScopeNodes);
    size_t k = 0;
    for (int i = 0; i < kScopeNodes; ++i) {
        const double s = kScopeLength * i / (kScopeNodes - 1);
        while (k + 2 < c.arcLength.size() && c.arcLength[k + 1] < s) {
            ++k;
        }
        const double w = std::clamp((s - c.arcLength[k]) / (c.arcLength[k + 1] - c.arcLength[k]), 0.0, 1.0);
        const Eigen::Vector3d p = (1 - w) * c.points[k] + w * c.points[k + 1];
        const Eigen::Vector3d n = ((1 - w) * c.normals[k] + w * c.normals[k + 1]).normalized();
        const double radius = (1 - w) * c.radius[k] + w * c.radius[k + 1];
        // Swing across the lumen every 25 cm, reaching 1 mm into the wall at the peaks.
        x.col(i) = p + (radius - kRadius + 1e-3) * std::sin(2.0 * std::numbers::pi * s / 0.25) * n;
    }
    return x;
}

void runContactStep(benchmark::State& state, double activeFraction)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const geometry::TriangleMesh& mesh = anatomy.physicsMesh;
    contact::ScopeWallContact contact(mesh);
    if (activeFraction < 1.0) {
        // The active region: the wall around the scope's distal part, by arc length.
        const double span = activeFraction * anatomy.centreline.length();
        std::vector<std::uint8_t> awake(static_cast<size_t>(mesh.numVertices()));
        for (int i = 0; i < mesh.numVertices(); ++i) {
            const double s = anatomy.physicsNodes[static_cast<size_t>(i)].arcLength;
            awake[static_cast<size_t>(i)] = s > kScopeLength - span && s <= kScopeLength ? 1 : 0;
        }
        contact.setActiveNodes(awake);
    }
    const Eigen::Matrix3Xd x = scopeAlongCentreline(anatomy.centreline);
    Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, kScopeNodes);
    v.row(2).setConstant(0.05);  // inserting at 5 cm/s
    const Eigen::Matrix3Xd previous = x - 1e-3 * v;
    Eigen::Matrix3Xd wall = mesh.vertices;
    const Eigen::Matrix3Xd wallV = Eigen::Matrix3Xd::Zero(3, mesh.numVertices());
    int iteration = 0;
    size_t contacts = 0;
    int visits = 0;
    for (auto _ : state) {
        const double wobble = 2e-4 * std::sin(0.1 * iteration++);
        wall.row(0) = mesh.vertices.row(0).array() + wobble;
        const contact::ContactResult& r = contact.compute(x, v, previous, kRadius, wall, wallV);
        contacts = r.contacts.size();
        visits = r.treeVisits;
        benchmark::DoNotOptimize(r.maxWallForce);
        benchmark::ClobberMemory();
    }
    state.counters["contacts"] = static_cast<double>(contacts);
    state.counters["treeVisits"] = visits;
    state.counters["enabledTriangles"] = contact.tree().numEnabledTriangles();
    state.counters["triangles"] = mesh.numTriangles();
}

void BM_ContactStepAllEnabled(benchmark::State& state)
{
    runContactStep(state, 1.0);
}
BENCHMARK(BM_ContactStepAllEnabled)->Unit(benchmark::kMicrosecond);

void BM_ContactStepActiveRegion(benchmark::State& state)
{
    runContactStep(state, 0.2);
}
BENCHMARK(BM_ContactStepActiveRegion)->Unit(benchmark::kMicrosecond);

}  // namespace
