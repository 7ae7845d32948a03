// Metrics from a hand-made recording whose values are known, benchmarks and
// domain scores from hand-computed numbers.
#include "scoring/Benchmarks.h"
#include "scoring/DomainScores.h"
#include "scoring/MetricDefinitions.h"
#include "scoring/SessionMetrics.h"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string_view>

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
    EXPECT_DOUBLE_EQ(m.at("colon_length"), 1.0) << "kept for re-scoring";
    for (const auto& [name, value] : m) {
        EXPECT_NE(scoring::findMetric(name), nullptr) << name << " is not declared";
    }
}

// Re-scoring reads the context back from the stored metrics and gets the
// same figures from the recording: with the geometric mucosa estimate on a
// colon of another length than the default, and with the renderer's figure.
TEST(Metrics, TheStoredMetricsGiveBackTheContextTheyWereScoredIn)
{
    scoring::ScoringContext context;
    context.colonLength = 1.2;
    context.lesionsPresent = 2;
    const scoring::MetricValues geometric = scoring::computeMetrics(handMade(), context);
    EXPECT_EQ(scoring::computeMetrics(handMade(), scoring::storedContext(geometric)), geometric);
    EXPECT_NE(scoring::computeMetrics(handMade(), {}).at("mucosa_visualised"),
              geometric.at("mucosa_visualised"))
        << "the default colon's length would change the estimate";
    context.mucosaSeen = 0.37;
    const scoring::MetricValues rendered = scoring::computeMetrics(handMade(), context);
    EXPECT_EQ(scoring::computeMetrics(handMade(), scoring::storedContext(rendered)), rendered);
    EXPECT_EQ(scoring::storedContext(rendered).mucosaSeen, 0.37);
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

// The renderer watched handMade()'s session: its lesion events replace the
// loop's lesion-in-view signal (which has no occlusion test).
scoring::MetricValues watched(std::vector<procedure::RecordedEvent> onScreen)
{
    procedure::Recording r = handMade();
    r.mergeEvents(onScreen);
    scoring::ScoringContext context;
    context.lesionsPresent = 2;
    return scoring::computeMetrics(r, context);
}

TEST(Metrics, AMarkOfALesionTheRendererShowedFindsIt)
{
    // Lesion 2 on screen 7.6-8.3 s (the loop: in view 7.5-8.2 s); marked at 8.0 s.
    const scoring::MetricValues m = watched({{0.0, EventKind::LesionOffScreen, "lesion 1"},
                                             {0.0, EventKind::LesionOffScreen, "lesion 2"},
                                             {7.6, EventKind::LesionOnScreen, "lesion 2"},
                                             {8.3, EventKind::LesionOffScreen, "lesion 2"}});
    EXPECT_EQ(m.at("lesions_from_renderer"), 1.0);
    EXPECT_EQ(m.at("lesions_detected"), 1.0);
    EXPECT_NEAR(m.at("time_to_detection"), 0.4, 1e-12) << "from its first coming on screen";
    EXPECT_EQ(m.at("false_lesion_marks"), 1.0) << "the mark at 8.5 s found nothing on screen";
}

TEST(Metrics, AMarkOfALesionAFoldHidFromTheRendererIsFalse)
{
    // The loop says lesion 2 was in view when marked at 8.0 s; the renderer
    // never showed it (a fold in front): no detection, two false marks.
    const scoring::MetricValues m = watched(
        {{0.0, EventKind::LesionOffScreen, "lesion 1"}, {0.0, EventKind::LesionOffScreen, "lesion 2"}});
    EXPECT_EQ(m.at("lesions_from_renderer"), 1.0);
    EXPECT_EQ(m.at("lesions_detected"), 0.0);
    EXPECT_EQ(m.at("lesions_missed"), 2.0);
    EXPECT_EQ(m.at("false_lesion_marks"), 2.0);
    EXPECT_FALSE(m.contains("time_to_detection"));
    // Without the renderer's events the loop's signal counts it.
    EXPECT_EQ(scoring::computeMetrics(handMade(), {}).at("lesions_from_renderer"), 0.0);
}

TEST(Metrics, TheRenderersSightingCountsWithinOneUpdateOfTheMark)
{
    // Lesion 1 on screen 8.55-9.2 s: the mark at 8.5 s (naming none: the
    // loop saw nothing yet) finds it, 0.05 s before its first update shows it.
    scoring::MetricValues m = watched({{0.0, EventKind::LesionOffScreen, "lesion 1"},
                                       {0.0, EventKind::LesionOffScreen, "lesion 2"},
                                       {8.55, EventKind::LesionOnScreen, "lesion 1"},
                                       {9.2, EventKind::LesionOffScreen, "lesion 1"}});
    EXPECT_EQ(m.at("lesions_detected"), 1.0);
    EXPECT_EQ(m.at("time_to_detection"), 0.0) << "marked before it came on screen: no negative time";
    EXPECT_EQ(m.at("false_lesion_marks"), 1.0) << "the mark at 8.0 s: lesion 2 was never on screen";
    // 0.15 s after the mark is beyond one update (0.1 s): no lesion found.
    m = watched({{0.0, EventKind::LesionOffScreen, "lesion 1"},
                 {0.0, EventKind::LesionOffScreen, "lesion 2"},
                 {8.65, EventKind::LesionOnScreen, "lesion 1"}});
    EXPECT_EQ(m.at("lesions_detected"), 0.0);
    EXPECT_EQ(m.at("false_lesion_marks"), 2.0);
}

TEST(Metrics, TwoLesionsOnScreenAtOneMarkAreFoundByTwoMarks)
{
    procedure::Recording r = handMade();
    std::erase_if(r.events, [](const auto& e) { return e.kind == EventKind::LesionMarked; });
    r.mergeEvents({{0.0, EventKind::LesionOffScreen, "lesion 1"},
                   {0.0, EventKind::LesionOffScreen, "lesion 2"},
                   {2.0, EventKind::LesionOnScreen, "lesion 1"},
                   {2.0, EventKind::LesionOnScreen, "lesion 2"},
                   {2.5, EventKind::LesionMarked, "lesion 2"},
                   {2.7, EventKind::LesionMarked, "lesion 2"},
                   {2.9, EventKind::LesionMarked, "lesion 2"}});
    scoring::ScoringContext context;
    context.lesionsPresent = 2;
    const scoring::MetricValues m = scoring::computeMetrics(r, context);
    // The first mark finds the lesion it names, the second the other one on
    // screen, the third a lesion already found: not false.
    EXPECT_EQ(m.at("lesions_detected"), 2.0);
    EXPECT_NEAR(m.at("time_to_detection"), (0.5 + 0.7) / 2.0, 1e-12);
    EXPECT_EQ(m.at("false_lesion_marks"), 0.0);
}

TEST(Recording, MergedEventsStayInTimeOrderWithTheRecordersFirstAtEqualTimes)
{
    procedure::Recording r;
    r.events = {{1.0, EventKind::LensWash, ""}, {2.0, EventKind::LesionMarked, "lesion 1"}};
    r.mergeEvents(
        {{0.5, EventKind::LesionOffScreen, "lesion 1"}, {2.0, EventKind::LesionOnScreen, "lesion 1"}});
    ASSERT_EQ(r.events.size(), 4U);
    EXPECT_EQ(r.events[0].kind, EventKind::LesionOffScreen);
    EXPECT_EQ(r.events[1].kind, EventKind::LensWash);
    EXPECT_EQ(r.events[2].kind, EventKind::LesionMarked);
    EXPECT_EQ(r.events[3].kind, EventKind::LesionOnScreen);
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

namespace {

// Every metric reads as words in the trainer (no identifiers): a label that
// starts with a capital, has no underscore, and is not shared.
TEST(MetricDefinitions, EveryMetricHasItsOwnLabelForPeople)
{
    std::set<std::string_view> seen;
    for (const scoring::MetricDefinition& d : scoring::metricDefinitions()) {
        ASSERT_FALSE(d.label.empty()) << d.name;
        EXPECT_TRUE(std::isupper(static_cast<unsigned char>(d.label.front()))) << d.label;
        EXPECT_EQ(d.label.find('_'), std::string_view::npos) << d.label;
        EXPECT_TRUE(seen.insert(d.label).second) << d.label << " labels two metrics";
    }
    EXPECT_EQ(scoring::findMetric("loops_n")->label, "N loops");
}

}  // namespace
