// Rendering cost on the headless host (OSMesa; llvmpipe unless a GPU driver
// is present): one endoscope frame at 640x480 of the default colon's visual
// mesh (~55,000 vertices), with the mapping from the physics mesh included,
// and one coverage update on the physics mesh.

#include "simcore/geometry/MeshMapping.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/render/CoverageTracker.h"
#include "simcore/render/EndoscopeView.h"
#include "simcore/render/OffscreenContext.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <limits>
#include <vector>

namespace {

using namespace colonosim;

constexpr int kWidth = 640;
constexpr int kHeight = 480;

const geometry::ColonAnatomy& anatomy()
{
    static const geometry::ColonAnatomy colon = geometry::buildProceduralColon({});
    return colon;
}

/// Looking along the colon from 8 cm in (the rectum), up the frame's normal.
render::CameraPose poseAlongColon(double arcLength)
{
    const geometry::Centreline& c = anatomy().centreline;
    size_t k = 0;
    while (k + 1 < c.arcLength.size() && c.arcLength[k] < arcLength) {
        ++k;
    }
    render::CameraPose pose;
    pose.position = c.points[k];
    pose.rotation.col(2) = c.tangents[k];
    pose.rotation.col(1) = c.normals[k];
    pose.rotation.col(0) = c.normals[k].cross(c.tangents[k]);
    return pose;
}

void endoscopeFrame(benchmark::State& state)
{
    render::OffscreenContext context(kWidth, kHeight);
    const render::WallSurface surface =
        render::buildWallSurface(anatomy().visualMesh, anatomy().centreline, render::WallFindings{});
    const geometry::MeshMapping mapping(anatomy().physicsMesh, surface.rest.vertices);
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    const render::CameraPose pose = poseAlongColon(0.08);
    // A slightly deformed colon, so the mapping does real work.
    Eigen::Matrix3Xd physics = anatomy().physicsMesh.vertices;
    physics.row(1).array() += 1e-3;
    Eigen::Matrix3Xd visual;
    for (auto _ : state) {
        mapping.apply(physics, visual);
        view.setWallPositions(visual);
        view.render(pose, {}, kWidth, kHeight);
        context.gl().Finish();
    }
    state.counters["frames_per_s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["visual_vertices"] = static_cast<double>(surface.rest.numVertices());
    state.counters["triangles"] = static_cast<double>(view.drawnTriangles());
    state.SetLabel(reinterpret_cast<const char*>(context.gl().GetString(GL_RENDERER)));
}
BENCHMARK(endoscopeFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

/// endoscopeFrame's frame with the most bleeding marks a view draws, all
/// ahead of the lens (9-15 cm along the colon, around the wall): the
/// per-fragment cost of the marks where they cover the image.
void endoscopeFrameWithBleeding(benchmark::State& state)
{
    render::OffscreenContext context(kWidth, kHeight);
    const render::WallSurface surface =
        render::buildWallSurface(anatomy().visualMesh, anatomy().centreline, render::WallFindings{});
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    std::vector<render::BleedingMark> marks;
    for (int k = 0; k < render::kMaxBleedingMarks; ++k) {
        const render::WallPlace place{0.09 + 0.06 * k / render::kMaxBleedingMarks, 0.7 * k};
        marks.push_back({render::wallPoint(anatomy().centreline, place), 0.003, 0.8});
    }
    view.setBleedingMarks(marks);
    const render::CameraPose pose = poseAlongColon(0.08);
    for (auto _ : state) {
        view.render(pose, {}, kWidth, kHeight);
        context.gl().Finish();
    }
    state.counters["marks"] = static_cast<double>(marks.size());
}
BENCHMARK(endoscopeFrameWithBleeding)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The CPU side of a frame: mapping, normals, upload.
void wallUpdate(benchmark::State& state)
{
    render::OffscreenContext context(kWidth, kHeight);
    const render::WallSurface surface =
        render::buildWallSurface(anatomy().visualMesh, anatomy().centreline, render::WallFindings{});
    const geometry::MeshMapping mapping(anatomy().physicsMesh, surface.rest.vertices);
    render::EndoscopeView view(context.gl(), surface, render::RenderParameters{});
    Eigen::Matrix3Xd physics = anatomy().physicsMesh.vertices;
    physics.row(1).array() += 1e-3;
    Eigen::Matrix3Xd visual;
    const bool withMapping = state.range(0) != 0;
    mapping.apply(physics, visual);
    for (auto _ : state) {
        if (withMapping) {
            mapping.apply(physics, visual);
        }
        view.setWallPositions(visual);
        context.gl().Finish();
    }
}
BENCHMARK(wallUpdate)->ArgName("mapping")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The draw alone at width x height, the levels of detail allowed
/// range(2) / 10 pixels of error (0: the full mesh everywhere), the lens
/// soiled range(3) percent (the droplet mask drawn once, as it is while the
/// soiling holds).
void endoscopeFrameDrawOnly(benchmark::State& state)
{
    const int width = static_cast<int>(state.range(0));
    const int height = static_cast<int>(state.range(1));
    render::OffscreenContext context(width, height);
    const render::WallSurface surface =
        render::buildWallSurface(anatomy().visualMesh, anatomy().centreline, render::WallFindings{});
    render::RenderParameters parameters;
    parameters.levelOfDetailError = static_cast<double>(state.range(2)) / 10.0;
    render::EndoscopeView view(context.gl(), surface, parameters);
    const render::CameraPose pose = poseAlongColon(0.08);
    const render::LensState lens{static_cast<double>(state.range(3)) / 100.0, 0.0,
                                 std::numeric_limits<double>::infinity()};
    for (auto _ : state) {
        view.render(pose, lens, width, height);
        context.gl().Finish();
    }
    state.counters["triangles"] = static_cast<double>(view.drawnTriangles());
}
BENCHMARK(endoscopeFrameDrawOnly)
    ->ArgNames({"width", "height", "lod_error_tenths_px", "soiling_percent"})
    ->Args({kWidth, kHeight, 10, 0})
    ->Args({kWidth, kHeight, 0, 0})
    ->Args({kWidth, kHeight, 10, 50})
    ->Args({320, 240, 10, 0})
    ->Args({320, 240, 0, 0})
    ->Args({320, 240, 10, 50})
    ->Args({64, 48, 10, 0})
    ->Args({64, 48, 0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void coverageUpdate(benchmark::State& state)
{
    render::OffscreenContext context(64, 64);
    std::vector<geometry::Segment> segments;
    for (const auto& t : anatomy().physicsMesh.triangles) {
        segments.push_back(anatomy().physicsNodes[static_cast<size_t>(t[0])].segment);
    }
    render::CoverageTracker tracker(context.gl(), anatomy().physicsMesh, segments,
                                    render::RenderParameters{});
    const render::CameraPose pose = poseAlongColon(0.08);
    for (auto _ : state) {
        tracker.observe(anatomy().physicsMesh.vertices, pose);
    }
    state.counters["triangles"] = static_cast<double>(anatomy().physicsMesh.numTriangles());
    state.counters["seen_fraction"] = tracker.fractionSeen();
}
BENCHMARK(coverageUpdate)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
