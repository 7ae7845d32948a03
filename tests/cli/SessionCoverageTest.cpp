// The renderer's coverage of a running session (% mucosa visualised): it
// grows as the scope goes in, depends on the simulated session only (a
// replay of the session's input trace covers the same wall, to the bit),
// and the loop's thread only hands the wall over.
#include "trainer_ui/cli/SessionCoverage.h"

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace colonosim;

struct Covered {
    double fraction = 0.0;
    int draws = 0;
    procedure::InputTrace trace;
    procedure::Recording recording;  ///< the loop's, with the renderer's lesion events
};

Covered run(const geometry::ColonAnatomy& anatomy, procedure::Operator& driver, double seconds,
            const procedure::ProcedureSettings& settings = {})
{
    procedure::ProcedureLoop loop(anatomy, settings);
    cli::SessionCoverage coverage(anatomy, cli::lesionTrianglesOf(loop.lesions()));
    double before = -1.0;
    const auto steps = static_cast<long>(seconds / loop.trace().loopStep);
    for (long s = 0; s < steps && !driver.finished(); ++s) {
        loop.step(driver.next(loop));
        coverage.observe(loop);
        if (s == steps / 2) {
            before = coverage.finalFraction();
        }
    }
    Covered out{coverage.finalFraction(), coverage.draws(), loop.trace(),
                cli::recordingSeenBy(loop, &coverage)};
    EXPECT_GT(before, 0.0);
    EXPECT_GE(out.fraction, before) << "coverage never shrinks";
    return out;
}

TEST(SessionCoverage, GrowsAsTheScopeGoesInAndAReplayCoversTheSameWall)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const Covered first = run(anatomy, expert, 3.0);
    // Ten hand-overs a simulated second, every one drawn.
    EXPECT_EQ(first.draws, 30);
    EXPECT_GT(first.fraction, 0.01);
    EXPECT_LT(first.fraction, 0.5) << "3 s in the rectum sees part of the colon";
    procedure::ReplayOperator replay(first.trace);
    const Covered again = run(anatomy, replay, 3.0);
    EXPECT_EQ(again.draws, first.draws);
    EXPECT_EQ(again.fraction, first.fraction) << "bit for bit: simulated time drives it, not the wall clock";
}

// The case's lesions are watched through the coverage's ID buffer: every
// lesion's state at the first draw, then each change, at the draws' times,
// merged into the loop's recording. A lesion ahead in the rectum comes on
// screen as the expert goes in; one in the transverse colon does not. A
// replay of the session gives the same events.
std::vector<procedure::RecordedEvent> renderedLesionEvents(const procedure::Recording& recording)
{
    std::vector<procedure::RecordedEvent> out;
    for (const auto& e : recording.events) {
        if (e.kind == procedure::EventKind::LesionOnScreen ||
            e.kind == procedure::EventKind::LesionOffScreen) {
            out.push_back(e);
        }
    }
    return out;
}

TEST(SessionCoverage, ALesionAheadComesOnScreenAndTheEventsJoinTheRecording)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ProcedureSettings settings;
    settings.lesions = {{0.08, 0.0}, {1.2, 0.0}};  // in the rectum; in the transverse colon
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const Covered first = run(anatomy, expert, 3.0, settings);
    using procedure::EventKind;
    const std::vector<procedure::RecordedEvent> rendered = renderedLesionEvents(first.recording);
    ASSERT_GE(rendered.size(), 3U);
    const double firstDraw = rendered[0].time;
    EXPECT_LT(firstDraw, 0.1);
    EXPECT_EQ(rendered[0].kind, EventKind::LesionOffScreen);
    EXPECT_EQ(rendered[0].detail, "lesion 1");
    EXPECT_EQ(rendered[1].kind, EventKind::LesionOffScreen);
    EXPECT_EQ(rendered[1].detail, "lesion 2");
    EXPECT_EQ(rendered[1].time, firstDraw);
    bool lesion1OnScreen = false;
    for (const auto& e : rendered) {
        EXPECT_NE(e.detail == "lesion 2" && e.kind == EventKind::LesionOnScreen, true)
            << "the transverse colon's lesion is not on screen from the rectum (at " << e.time << " s)";
        lesion1OnScreen = lesion1OnScreen || (e.detail == "lesion 1" && e.kind == EventKind::LesionOnScreen);
        const double draws = (e.time - firstDraw) / 0.1;
        EXPECT_NEAR(draws, std::round(draws), 0.02) << "events come at the draws, 10 a simulated second";
    }
    EXPECT_TRUE(lesion1OnScreen) << "the rectal lesion 8 cm in comes on screen in 3 s";
    EXPECT_TRUE(std::is_sorted(first.recording.events.begin(), first.recording.events.end(),
                               [](const auto& a, const auto& b) { return a.time < b.time; }));

    procedure::ReplayOperator replay(first.trace);
    const Covered again = run(anatomy, replay, 3.0, settings);
    const std::vector<procedure::RecordedEvent> replayed = renderedLesionEvents(again.recording);
    ASSERT_EQ(replayed.size(), rendered.size());
    for (size_t k = 0; k < rendered.size(); ++k) {
        EXPECT_EQ(replayed[k].time, rendered[k].time);
        EXPECT_EQ(replayed[k].kind, rendered[k].kind);
        EXPECT_EQ(replayed[k].detail, rendered[k].detail);
    }
}

}  // namespace
