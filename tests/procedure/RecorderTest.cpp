// The recorder: sample rate, events on edges with exact times, and a
// canonical text that changes with any bit of any recorded value.

#include "simcore/procedure/Recorder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::procedure {
namespace {

std::vector<EventKind> kinds(const Recording& r)
{
    std::vector<EventKind> out;
    for (const auto& e : r.events) {
        out.push_back(e.kind);
    }
    return out;
}

TEST(Recorder, SamplesAtOneHundredHertz)
{
    Recorder recorder(RecorderParameters{});
    for (int step = 0; step < 2000; ++step) {
        ProcedureFrame f;
        f.time = step * 1e-3;
        recorder.record(f);
    }
    EXPECT_EQ(recorder.recording().samples.size(), 200U);
    EXPECT_DOUBLE_EQ(recorder.recording().samples[37].time, 0.37);
}

TEST(Recorder, EventsFireOnceOnEachEdgeAtTheExactStep)
{
    RecorderParameters p;
    p.colonLength = 1.0;
    Recorder recorder(p);
    for (int step = 0; step < 1000; ++step) {
        ProcedureFrame f;
        f.time = step * 1e-3;
        f.handleForce = step >= 100 && step < 200 ? 20.0 : 5.0;                 // excessive 100-199
        f.loop = step >= 300 && step < 400 ? LoopKind::Alpha : LoopKind::None;  // alpha 300-399
        f.input.buttons = step >= 500 && step < 520 ? kWater : 0;               // one press
        f.input.buttons |= step >= 600 && step < 610 ? kMarkLesion : 0;
        f.lensWallDistance = step >= 700 && step < 750 ? 0.001 : 0.02;  // red-out 700-749
        f.tipArcLength = step >= 800 ? 0.99 : 0.5;                      // cecum at 800
        if (step >= 900) {
            f.tipDirection = -f.colonTangentAtTip;  // retroflexed from 900
        }
        recorder.record(f);
    }
    const std::vector<EventKind> expected{
        EventKind::ExcessiveForceStart, EventKind::ExcessiveForceEnd, EventKind::LoopFormed,
        EventKind::LoopResolved,        EventKind::LensWash,          EventKind::LesionMarked,
        EventKind::RedOutStart,         EventKind::RedOutEnd,         EventKind::CecumReached,
        EventKind::Retroflexion};
    EXPECT_EQ(kinds(recorder.recording()), expected);
    const auto& events = recorder.recording().events;
    EXPECT_DOUBLE_EQ(events[0].time, 0.100);
    EXPECT_DOUBLE_EQ(events[1].time, 0.200);
    EXPECT_EQ(events[2].detail, "alpha");
    EXPECT_EQ(events[3].detail, "alpha");
    EXPECT_DOUBLE_EQ(events[8].time, 0.800);
}

TEST(Recorder, CanonicalTextSeesOneUlp)
{
    const auto run = [](double nudge) {
        Recorder recorder(RecorderParameters{});
        for (int step = 0; step < 100; ++step) {
            ProcedureFrame f;
            f.time = step * 1e-3;
            f.handleForce = 3.0 + (step == 50 ? nudge : 0.0);
            recorder.record(f);
        }
        return recorder.recording().canonicalText();
    };
    EXPECT_EQ(run(0.0), run(0.0));
    EXPECT_NE(run(0.0), run(std::nextafter(3.0, 4.0) - 3.0));
}

TEST(Recorder, RefusesASampleRateBelowOneHundredHertz)
{
    RecorderParameters p;
    p.sampleInterval = 0.05;
    EXPECT_THROW(Recorder{p}, params::ParameterError);
}

}  // namespace
}  // namespace colonosim::procedure
