// Metrics from a hand-made recording whose values are known, benchmarks and
// domain scores from hand-computed numbers.
#include "scoring/Benchmarks.h"
#include "scoring/DomainScores.h"
#include "scoring/MetricDefinitions.h"
#include "scoring/SessionMetrics.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;
using procedure::EventKind;

// 10 s at 100 Hz; insertion 0 -> 0.5 m over 5 s then back to 0.3 m; handle
// force 20 N between 2 and 3 s, else 5 N; an alpha loop from 1 to 4 s
// (resolved); red-out from 6 to 7 s; cecum reached at 4 s; discomfort 7 from
// 3 to 5 s; one lesion marked of two present.
procedure::Recording handMade()
{
    procedure::Recording r;
    for (int k = 0; k <= 1000; ++k) {
        const double t = 0.01 * k;
        procedure::RecordedSample s{};
        s.time = t;
        s.insertion = t <= 5.0 ? 0.1 * t : 0.5 - 0.04 * (t - 5.0);
        s.tip = Eigen::Vector3d(0.0, 0.0, s.insertion);
        s.handleForce = (t >= 2.0 && t < 3.0) ? 20.0 : 5.0;
        s.handleTorque = -0.1;
        s.discomfort = (t >= 3.0 && t < 5.0) ? 7.0 : 1.0;
        s.loop = (t >= 1.0 && t < 4.0) ? procedure::LoopKind::Alpha : procedure::LoopKind::None;
        r.samples.push_back(s);
    }
    r.events = {{1.0, EventKind::LoopFormed, std::string(procedure::loopName(procedure::LoopKind::Alpha))},
                {4.0, EventKind::LoopResolved, ""},
                {4.0, EventKind::CecumReached, ""},
                {6.0, EventKind::RedOutStart, ""},
                {7.0, EventKind::RedOutEnd, ""},
                {7.5, EventKind::LesionInView, "lesion 2"},
                {8.0, EventKind::LesionMarked, "lesion 2"},
                {8.2, EventKind::LesionOutOfView, "lesion 2"},
                {8.5, EventKind::LesionMarked, "none in view"},
                {9.0, EventKind::LesionInView, "lesion 1"},
                {9.5, EventKind::LesionOutOfView, "lesion 1"}};
    return r;
}

TEST(Metrics, FromAHandMadeRecording)
{
    scoring::ScoringContext context;
    context.colonLength = 1.0;
    context.lesionsPresent = 2;
    const scoring::MetricValues m = scoring::computeMetrics(handMade(), context);
    // Sums of 0.01 s sample intervals: tolerance of one interval.
    constexpr double dt = 0.0101;
    EXPECT_DOUBLE_EQ(m.at("total_time"), 10.0);
    EXPECT_DOUBLE_EQ(m.at("time_to_cecum"), 4.0);
    EXPECT_DOUBLE_EQ(m.at("cecal_intubation"), 1.0);
    EXPECT_DOUBLE_EQ(m.at("withdrawal_time"), 6.0);
    EXPECT_DOUBLE_EQ(m.at("effective_withdrawal_time"), 5.0);
    EXPECT_DOUBLE_EQ(m.at("clear_view"), 0.9);
    EXPECT_EQ(m.at("red_out_count"), 1.0);
    EXPECT_EQ(m.at("loop_count"), 1.0);
    EXPECT_EQ(m.at("loops_alpha"), 1.0);
    EXPECT_EQ(m.at("loops_n"), 0.0);
    EXPECT_EQ(m.at("loops_reduced"), 1.0);
    EXPECT_NEAR(m.at("looped_time"), 3.0, dt);
    EXPECT_NEAR(m.at("excessive_force_time"), 1.0, dt);  // 20 N > 15 N threshold
    EXPECT_DOUBLE_EQ(m.at("max_handle_force"), 20.0);
    EXPECT_NEAR(m.at("mean_handle_force"), 5.0 + 15.0 * 100.0 / 1001.0, 1e-9);
    EXPECT_DOUBLE_EQ(m.at("max_handle_torque"), 0.1);
    EXPECT_DOUBLE_EQ(m.at("discomfort_peak"), 7.0);
    EXPECT_NEAR(m.at("discomfort_moderate_share"), 0.2, dt / 10.0);
    EXPECT_EQ(m.at("perforation"), 0.0);
    // Lesion 2 marked 0.5 s after it came into view; lesion 1 seen, never
    // marked; one mark with nothing in view.
    EXPECT_EQ(m.at("lesions_detected"), 1.0);
    EXPECT_EQ(m.at("lesions_missed"), 1.0);
    EXPECT_DOUBLE_EQ(m.at("time_to_detection"), 0.5);
    EXPECT_EQ(m.at("false_lesion_marks"), 1.0);
    EXPECT_NEAR(m.at("tip_path_length"), 0.5 + 0.2, 1e-9);
    EXPECT_NEAR(m.at("insertion_efficiency"), 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(m.at("max_insertion"), 0.5);
    // Bins of 1 cm over 1 m; insertion covers 0-50 cm (bins 0..50 minus none: the
    // red-out from 6 to 7 s only repeats depths seen on the way in).
    EXPECT_NEAR(m.at("mucosa_visualised"), 0.51, 1e-9);
    for (const auto& [name, value] : m) {
        EXPECT_NE(scoring::findMetric(name), nullptr) << name << " is not declared";
    }
}

TEST(Metrics, TheCecumNotReachedLeavesTimeToCecumAbsent)
{
    procedure::Recording r = handMade();
    std::erase_if(r.events, [](const auto& e) { return e.kind == EventKind::CecumReached; });
    const scoring::MetricValues m = scoring::computeMetrics(r, {});
    EXPECT_FALSE(m.contains("time_to_cecum"));
    EXPECT_EQ(m.at("cecal_intubation"), 0.0);
    EXPECT_EQ(m.at("withdrawal_time"), 0.0);
}

// Effective withdrawal: the cecum at 4 s, the session ends at 10 s; red-out
// 6-7 s (from handMade) plus the cleaning given here.
double effectiveWithdrawal(std::vector<procedure::RecordedEvent> cleaning)
{
    procedure::Recording r = handMade();
    r.events.insert(r.events.end(), cleaning.begin(), cleaning.end());
    return scoring::computeMetrics(r, {}).at("effective_withdrawal_time");
}

TEST(Metrics, EffectiveWithdrawalLessTheUnionOfRedOutAndCleaning)
{
    // Cleaning 6.5-8 s overlaps the red-out 6-7 s: together 6-8 s, 2 s, not 2.5 s.
    EXPECT_DOUBLE_EQ(
        effectiveWithdrawal({{6.5, EventKind::CleaningStart, ""}, {8.0, EventKind::CleaningEnd, ""}}), 4.0);
    // Cleaning 3-4.5 s: only the 0.5 s after the cecum counts; disjoint from the red-out.
    EXPECT_DOUBLE_EQ(
        effectiveWithdrawal({{3.0, EventKind::CleaningStart, ""}, {4.5, EventKind::CleaningEnd, ""}}), 4.5);
    // Cleaning inside the red-out takes nothing more away.
    EXPECT_DOUBLE_EQ(
        effectiveWithdrawal({{6.2, EventKind::CleaningStart, ""}, {6.8, EventKind::CleaningEnd, ""}}), 5.0);
}

TEST(Metrics, ASessionEndingWhileCleaningIsClosedAtTheEnd)
{
    // Cleaning from 9 s to the end (10 s) without an end event: 1 s, plus the red-out's 1 s.
    EXPECT_DOUBLE_EQ(effectiveWithdrawal({{9.0, EventKind::CleaningStart, ""}}), 4.0);
}

TEST(Benchmarks, MeanSdLimitsAndProficiency)
{
    const std::vector<scoring::MetricValues> experts = {
        {{"max_handle_force", 8.0}, {"clear_view", 0.9}},
        {{"max_handle_force", 10.0}, {"clear_view", 0.8}},
        {{"max_handle_force", 12.0}, {"clear_view", 0.7}},
    };
    const auto set = scoring::deriveBenchmarks("b", 2, 1.0, experts);
    ASSERT_EQ(set.metrics.size(), 2u);
    EXPECT_DOUBLE_EQ(set.metrics.at("max_handle_force").mean, 10.0);
    EXPECT_DOUBLE_EQ(set.metrics.at("max_handle_force").sd, 2.0);
    EXPECT_DOUBLE_EQ(set.limit("max_handle_force"), 12.0);  // lower is better: mean + k SD
    EXPECT_NEAR(set.limit("clear_view"), 0.7, 1e-12);       // higher is better: mean - k SD
    EXPECT_DOUBLE_EQ(*set.proficiency("max_handle_force", 11.0), 1.0);
    EXPECT_DOUBLE_EQ(*set.proficiency("max_handle_force", 15.0), 0.5);  // 3 N past the limit = 1.5 SD of 3 SD
    EXPECT_DOUBLE_EQ(*set.proficiency("max_handle_force", 30.0), 0.0);
    EXPECT_FALSE(set.proficiency("total_time", 1.0).has_value());
    EXPECT_TRUE(set.met({{"max_handle_force", 12.0}, {"clear_view", 0.75}}));
    EXPECT_FALSE(set.met({{"max_handle_force", 12.5}, {"clear_view", 0.75}}));
    EXPECT_FALSE(set.met({{"max_handle_force", 12.0}}));  // a benchmarked metric missing fails
    const auto back = scoring::BenchmarkSet::fromJson(set.toJson());
    EXPECT_EQ(back.version, 2);
    EXPECT_DOUBLE_EQ(back.metrics.at("clear_view").sd, set.metrics.at("clear_view").sd);
    EXPECT_THROW((void)scoring::BenchmarkSet::fromJson(R"({"name":"b","version":1,"k":9,"metrics":{}})"),
                 std::invalid_argument);
    EXPECT_THROW(
        (void)scoring::BenchmarkSet::fromJson(R"({"name":"b","version":1,"k":1,"metrics":{"x":{}}})"),
        std::invalid_argument);
}

TEST(DomainScores, MapProficiencyToTheScales)
{
    const auto set = scoring::deriveBenchmarks(
        "b", 1, 1.0,
        {{{"clear_view", 0.9}, {"red_out_count", 1.0}}, {{"clear_view", 0.7}, {"red_out_count", 3.0}}});
    // clear_view: mean 0.8, sd 0.1414 -> limit 0.6586; red_out_count: mean 2, sd 1.414 -> limit 3.414.
    const auto perfect = scoring::scoreSession({{"clear_view", 0.95}, {"red_out_count", 0.0}}, set);
    EXPECT_DOUBLE_EQ(perfect.at("gages_clear_field"), 5.0);
    EXPECT_DOUBLE_EQ(perfect.at("dops_tip_control"), 4.0);
    EXPECT_DOUBLE_EQ(perfect.at("composite"), 100.0);
    EXPECT_FALSE(perfect.contains("gages_navigation"));  // no benchmarked metric of that domain
    const auto worst = scoring::scoreSession({{"clear_view", 0.0}, {"red_out_count", 20.0}}, set);
    EXPECT_DOUBLE_EQ(worst.at("gages_clear_field"), 1.0);
    EXPECT_DOUBLE_EQ(worst.at("dops_tip_control"), 1.0);
    EXPECT_DOUBLE_EQ(worst.at("composite"), 0.0);
}

}  // namespace
