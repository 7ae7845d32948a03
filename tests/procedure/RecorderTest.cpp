// The recorder: sample rate, events on edges with exact times, and a
// canonical text that changes with any bit of any recorded value.

#include "simcore/procedure/Recorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

TEST(Recorder, SampleValuesAreRoundedToTheDeclaredResolution)
{
    Recorder recorder(RecorderParameters{});
    ProcedureFrame f;
    f.tipPosition = {0.1234567891, -0.0456789123, 0.3};
    f.handleForce = 3.14159265;
    f.maxWallForce = 0.000123;  // below half a step: rounds to zero
    f.handleTorque = -0.0123456;
    f.mesenteryStrain = 0.0345678;
    f.discomfort = 4.56789;
    recorder.record(f);
    const RecordedSample& s = recorder.recording().samples.at(0);
    using R = RecordingResolution;
    const auto onGrid = [](double value, double step) { return std::fmod(value, step) == 0.0; };
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_TRUE(onGrid(s.tip[axis], R::positionSpec.defaultValue)) << axis;
        EXPECT_LE(std::abs(s.tip[axis] - f.tipPosition[axis]), 0.5 * R::positionSpec.defaultValue) << axis;
    }
    EXPECT_TRUE(onGrid(s.handleForce, R::forceSpec.defaultValue));
    EXPECT_NEAR(s.handleForce, f.handleForce, 0.5 * R::forceSpec.defaultValue);
    EXPECT_EQ(s.maxWallForce, 0.0);
    EXPECT_TRUE(onGrid(s.handleTorque, R::torqueSpec.defaultValue));
    EXPECT_NEAR(s.handleTorque, f.handleTorque, 0.5 * R::torqueSpec.defaultValue);
    EXPECT_NEAR(s.mesenteryStrain, f.mesenteryStrain, 0.5 * R::strainSpec.defaultValue);
    EXPECT_NEAR(s.discomfort, f.discomfort, 0.5 * R::discomfortSpec.defaultValue);
    EXPECT_NE(s.discomfort, f.discomfort);  // it was rounded, not copied
    // Rounding again changes nothing: what is stored is what was scored.
    EXPECT_EQ(quantizeSample(s).handleForce, s.handleForce);
    EXPECT_EQ(quantizeSample(s).tip, s.tip);
}

TEST(Recorder, LesionsComingIntoViewAndMarksNameTheLesion)
{
    Recorder recorder(RecorderParameters{});
    const auto at = [&](int step, std::uint32_t inView, bool mark) {
        ProcedureFrame f;
        f.time = step * 1e-3;
        f.lesionsInView = inView;
        f.input.buttons = mark ? kMarkLesion : 0;
        recorder.record(f);
    };
    at(0, 0, true);       // a mark with nothing in view
    at(1, 0, false);      // released
    at(2, 0b100, false);  // lesion 3 comes into view
    at(3, 0b110, true);   // lesion 2 too; the mark names the first in view
    at(4, 0b010, false);  // lesion 3 leaves
    const auto& e = recorder.recording().events;
    ASSERT_EQ(e.size(), 5U);
    EXPECT_EQ(e[0].kind, EventKind::LesionMarked);
    EXPECT_EQ(e[0].detail, "none in view");
    EXPECT_EQ(e[1].kind, EventKind::LesionInView);
    EXPECT_EQ(e[1].detail, "lesion 3");
    EXPECT_DOUBLE_EQ(e[1].time, 0.002);
    EXPECT_EQ(e[2].kind, EventKind::LesionInView);
    EXPECT_EQ(e[2].detail, "lesion 2");
    EXPECT_EQ(e[3].kind, EventKind::LesionMarked);
    EXPECT_EQ(e[3].detail, "lesion 2");
    EXPECT_EQ(e[4].kind, EventKind::LesionOutOfView);
    EXPECT_EQ(e[4].detail, "lesion 3");
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
        EventKind::LoopResolved,        EventKind::LensWash,          EventKind::CleaningStart,
        EventKind::CleaningEnd,         EventKind::LesionMarked,      EventKind::RedOutStart,
        EventKind::RedOutEnd,           EventKind::CecumReached,      EventKind::Retroflexion};
    EXPECT_EQ(kinds(recorder.recording()), expected);
    const auto& events = recorder.recording().events;
    EXPECT_DOUBLE_EQ(events[0].time, 0.100);
    EXPECT_DOUBLE_EQ(events[1].time, 0.200);
    EXPECT_EQ(events[2].detail, "alpha");
    EXPECT_EQ(events[3].detail, "alpha");
    EXPECT_DOUBLE_EQ(events[10].time, 0.800);
}

TEST(Recorder, CleaningRunsFromTheFirstStepWithWaterOrSuctionHeldToTheFirstWithNeither)
{
    Recorder recorder(RecorderParameters{});
    for (int step = 0; step < 100; ++step) {
        ProcedureFrame f;
        f.time = step * 1e-3;
        // water 10-29, suction 20-39 (one cleaning 10-39), air alone 50-59
        // (not cleaning), suction again from 70 to the end (left open).
        f.input.buttons = (step >= 10 && step < 30 ? kWater : 0) | (step >= 20 && step < 40 ? kSuction : 0) |
                          (step >= 50 && step < 60 ? kAir : 0) | (step >= 70 ? kSuction : 0);
        recorder.record(f);
    }
    const auto& e = recorder.recording().events;
    const std::vector<EventKind> expected{EventKind::LensWash, EventKind::CleaningStart,
                                          EventKind::CleaningEnd, EventKind::CleaningStart};
    ASSERT_EQ(kinds(recorder.recording()), expected);
    EXPECT_DOUBLE_EQ(e[0].time, 0.010);  // the lens wash stays on the water button's press
    EXPECT_DOUBLE_EQ(e[1].time, 0.010);
    EXPECT_DOUBLE_EQ(e[2].time, 0.040);
    EXPECT_DOUBLE_EQ(e[3].time, 0.070);
    EXPECT_EQ(eventName(EventKind::CleaningStart), "cleaning_start");
    EXPECT_EQ(eventName(EventKind::CleaningEnd), "cleaning_end");
}

TEST(Recorder, CanonicalTextSeesOneUlp)
{
    // The text compares recordings bit for bit, so it must show every bit of
    // a value (the recorder rounds what it records; the text must not).
    const auto text = [](double force) {
        Recording recording;
        recording.samples.push_back(RecordedSample{0.01, 0.0, Eigen::Vector3d::Zero(),
                                                   geometry::Segment::Rectum, force, 0.0, 0.0, 0.0, 0.0,
                                                   LoopKind::None});
        return recording.canonicalText();
    };
    EXPECT_EQ(text(3.0), text(3.0));
    EXPECT_NE(text(3.0), text(std::nextafter(3.0, 4.0)));
}

TEST(Recorder, RefusesASampleRateBelowOneHundredHertz)
{
    RecorderParameters p;
    p.sampleInterval = 0.05;
    EXPECT_THROW(Recorder{p}, params::ParameterError);
}

TEST(Recorder, RefusesACecumDepthOutsideItsRangeByName)
{
    RecorderParameters p;
    p.cecumDepth = -0.01;
    try {
        Recorder recorder{p};
        FAIL() << "a negative cecum depth was accepted";
    } catch (const params::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("recorder.cecumDepth"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace colonosim::procedure
