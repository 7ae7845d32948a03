// Texture charts of the wall compared: the centreline chart (nearest
// centreline sample) against the Laplace chart (harmonic along-coordinate).
// Prints each chart's distortion (stretch sigma1/sigma2, area ratio, tears)
// on the default colon and a colon with tight flexures,
// (the straight tube is a test: both are 1 there), then times both chart builds on the default colon's visual
// mesh.

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/render/CentrelineChart.h"
#include "simcore/render/ChartDistortion.h"
#include "simcore/render/LaplaceChart.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

namespace {

using namespace colonosim;

/// Short sigmoid and flexures (the minimum lengths) in the widest lumen the
/// parameters allow: the layout's bends are at their tightest.
geometry::AnatomyParameters tightFlexures()
{
    geometry::AnatomyParameters p;
    p.sigmoidLength = 0.20;
    p.splenicFlexureLength = 0.04;
    p.hepaticFlexureLength = 0.04;
    p.sigmoidDiameter = geometry::AnatomyParameters::sigmoidDiameterSpec.maxValue;
    p.splenicFlexureDiameter = geometry::AnatomyParameters::splenicFlexureDiameterSpec.maxValue;
    p.hepaticFlexureDiameter = geometry::AnatomyParameters::hepaticFlexureDiameterSpec.maxValue;
    return p;
}

const geometry::ColonAnatomy& defaultColon()
{
    static const geometry::ColonAnatomy colon = geometry::buildProceduralColon({});
    return colon;
}

void printRow(const char* scene, const char* chart, const render::ChartDistortion& d)
{
    std::printf("| %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %d of %d |\n", scene, chart,
                d.stretch.mean, d.stretch.p95, d.stretch.p99, d.stretch.max, d.areaRatio.p95, d.areaRatio.p99,
                d.areaRatio.max, d.numTears, d.numTriangles);
}

void compare(const char* scene, const geometry::TriangleMesh& mesh, const geometry::Centreline& centreline)
{
    const std::vector<int> nearest = render::nearestCentrelineSamples(mesh, centreline);
    printRow(scene, "centreline",
             render::measureChartDistortion(mesh, render::centrelineChart(mesh, centreline, nearest)));
    printRow(scene, "Laplace", render::measureChartDistortion(mesh, render::laplaceChart(mesh, centreline)));
}

void centrelineChartBuild(benchmark::State& state)
{
    const geometry::ColonAnatomy& colon = defaultColon();
    for (auto _ : state) {
        const std::vector<int> nearest = render::nearestCentrelineSamples(colon.visualMesh, colon.centreline);
        benchmark::DoNotOptimize(render::centrelineChart(colon.visualMesh, colon.centreline, nearest));
    }
}
BENCHMARK(centrelineChartBuild)->Unit(benchmark::kMillisecond);

void laplaceChartBuild(benchmark::State& state)
{
    const geometry::ColonAnatomy& colon = defaultColon();
    for (auto _ : state) {
        benchmark::DoNotOptimize(render::laplaceChart(colon.visualMesh, colon.centreline));
    }
}
BENCHMARK(laplaceChartBuild)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv)
{
    std::printf("| scene | chart | stretch mean | p95 | p99 | max | area ratio p95 | p99 | max | tears |\n"
                "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    const geometry::ColonAnatomy& colon = defaultColon();
    compare("default colon", colon.visualMesh, colon.centreline);
    const geometry::ColonAnatomy tight = geometry::buildProceduralColon(tightFlexures());
    compare("tight flexures", tight.visualMesh, tight.centreline);
    std::fflush(stdout);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
