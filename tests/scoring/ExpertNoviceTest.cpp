// Scoring of recorded sessions: on ten generated patients (seeds 1-10), the
// scripted expert's composite score is above the scripted novice's. Each run
// is 10 s of simulated time (a whole run takes the expert 60-120 s, several
// minutes of a core each), so what is scored is the first part of the
// insertion: forces, loops, view, discomfort, pace, the wall seen.
// Benchmarks come from the expert on three other patients (seeds 101-103),
// so no run is scored against itself.
#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSpec.h"
#include "scoring/Benchmarks.h"
#include "scoring/DomainScores.h"
#include "scoring/SessionMetrics.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"

#include <gtest/gtest.h>

#include <iostream>

namespace {

using namespace colonosim;

constexpr double kRunTime = 10.0;  ///< s simulated per run

scoring::MetricValues runOnce(std::uint64_t seed, const std::string& operatorName)
{
    const cases::Case patient = cases::CaseGenerator().generate(seed);
    const cases::SceneSpec scene = cases::toScene(patient);
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    procedure::ProcedureSettings settings;
    settings.tissue = scene.tissue;
    settings.environment = scene.environment;
    procedure::ProcedureLoop loop(anatomy, settings);
    auto driver = procedure::makeOperator(operatorName);
    const auto steps = static_cast<long>(kRunTime / loop.trace().loopStep);
    for (long s = 0; s < steps && !driver->finished(); ++s) {
        loop.step(driver->next(loop));
    }
    scoring::ScoringContext context;
    context.colonLength = loop.colonLength();
    context.lesionsPresent = static_cast<int>(patient.lesions.size());
    return scoring::computeMetrics(loop.recording(), context);
}

TEST(Scoring, TheExpertScoresAboveTheNoviceOnTenPatients)
{
    std::vector<scoring::MetricValues> experts;
    for (std::uint64_t seed : {101u, 102u, 103u}) {
        experts.push_back(runOnce(seed, "expert"));
    }
    const scoring::BenchmarkSet benchmarks = scoring::deriveBenchmarks("test", 1, 1.0, experts);
    ASSERT_FALSE(benchmarks.metrics.empty());
    int expertWins = 0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const auto expert = scoring::scoreSession(runOnce(seed, "expert"), benchmarks);
        const auto novice = scoring::scoreSession(runOnce(seed, "novice"), benchmarks);
        std::cout << "seed " << seed << ": expert " << expert.at("composite") << ", novice "
                  << novice.at("composite") << '\n';
        EXPECT_GT(expert.at("composite"), novice.at("composite")) << "seed " << seed;
        expertWins += expert.at("composite") > novice.at("composite") ? 1 : 0;
    }
    EXPECT_EQ(expertWins, 10);
}

}  // namespace
