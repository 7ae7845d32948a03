// Cases generated to XML in memory per second, single thread (issue 4:
// target >= 10,000/s). BM_GenerateCaseToXml is the figure: generate a case
// from its seed and write its XML to a string. The others split that time
// into generation and writing, time reading it back, and a constrained case
// (rejection sampling: "flat_lesion(6-9mm, right)" is met by about 1 case in
// 300).

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseReader.h"
#include "case_generator/CaseWriter.h"

#include <benchmark/benchmark.h>

namespace {

using namespace colonosim::cases;

void BM_GenerateCaseToXml(benchmark::State& state)
{
    const CaseGenerator generator;
    std::uint64_t seed = 0;
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string xml = writeCase(generator.generate(seed++));
        bytes += xml.size();
        benchmark::DoNotOptimize(xml.data());
    }
    state.counters["cases/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["bytes/case"] = static_cast<double>(bytes) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_GenerateCaseToXml);

void BM_GenerateCase(benchmark::State& state)
{
    const CaseGenerator generator;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(generator.generate(seed++));
    }
    state.counters["cases/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GenerateCase);

void BM_WriteCase(benchmark::State& state)
{
    const Case c = CaseGenerator().generate(2024);
    for (auto _ : state) {
        benchmark::DoNotOptimize(writeCase(c));
    }
}
BENCHMARK(BM_WriteCase);

void BM_ReadAndValidateCase(benchmark::State& state)
{
    const std::string xml = writeCase(CaseGenerator().generate(2024));
    for (auto _ : state) {
        benchmark::DoNotOptimize(readCase(xml, "case.xml"));
    }
}
BENCHMARK(BM_ReadAndValidateCase);

void BM_GenerateConstrainedCaseToXml(benchmark::State& state)
{
    const CaseGenerator generator;
    Constraints constraints;
    constraints.require = RequireExpression::parse("flat_lesion(6-9mm, right)");
    std::uint64_t seed = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(writeCase(generator.generate(seed++, constraints)));
    }
    state.counters["cases/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GenerateConstrainedCaseToXml);

}  // namespace
