// The coupled procedure loop on the default colon: it stays stable under the
// scripted expert and under hard input, refuses bad device input at the
// boundary, and a recorded input trace replays to a bit-identical recording.

#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/contact/LumenTube.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/StabilityBound.h"
#include "simcore/procedure/Operator.h"
#include "tests/procedure/LoopObservation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace colonosim;
using procedure::InputSample;
using procedure::ProcedureLoop;
using procedure::ProcedureSettings;

using looptest::defaultColon;
using looptest::observe;
using looptest::runOperator;
using looptest::RunSummary;

// Three seconds of the expert: the scope reaches the rectal curve and touches
// the wall. No tissue step is rejected, nothing is non-finite, and the handle
// force stays within the haptic device's 25 N.
TEST(ProcedureLoop, TheExpertRunsStably)
{
    ProcedureLoop loop(defaultColon(), ProcedureSettings{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const RunSummary summary = runOperator(loop, expert, 3500);
    EXPECT_TRUE(summary.finite);
    EXPECT_EQ(loop.tissue().rejectedSteps(), 0);
    EXPECT_LT(summary.peakHandleForce, 25.0);
    EXPECT_GT(loop.scope().numInsertedNodes(), 4) << "the scope went in";
    EXPECT_GT(loop.recording().samples.size(), 300U) << "100 Hz samples";
    EXPECT_TRUE(loop.bleedingMarks().empty()) << "the expert does not press the wall";
}

// The wall's stiffness-proportional damping gives the declared damping
// ratio of 0.39 in the default colon's highest mode (tissue.dampingTime),
// the Gershgorin bound stays above that mode's frequency, and the stepping
// plan of the loop at rest takes the symplectic Euler steps that the bound
// allows for that damping: 14 a loop step (0.2 of damping would allow 12;
// see the parameter for why it is not taken).
TEST(ProcedureLoop, TheWallIsDampedAsDeclaredInItsHighestMode)
{
    const ProcedureLoop loop(defaultColon(), ProcedureSettings{});
    const physics::TopMode top = physics::powerIterationTopMode(loop.colon().body, 3000);
    std::cout << "highest mode " << top.omega << " rad/s, damping ratio " << top.dampingRatio << "; "
              << loop.tissue().planNote() << "\n";
    EXPECT_NEAR(top.dampingRatio, 0.39, 0.02);
    EXPECT_GT(top.omega, 12000.0);
    const physics::StabilityEstimate bound = physics::estimateStability(loop.colon().body);
    EXPECT_GE(bound.omegaMax, top.omega) << "the bound is above the mode that power iteration converges to";
    EXPECT_EQ(loop.tissue().substeps(), 14) << loop.tissue().planNote();
}

// A session is determined by the case, the build and the input trace:
// replaying the recorded trace gives the same recording, bit for bit.
TEST(ProcedureLoop, ReplayIsBitIdentical)
{
    ProcedureLoop first(defaultColon(), ProcedureSettings{});
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    runOperator(first, novice, 2500);
    ProcedureLoop second(defaultColon(), ProcedureSettings{});
    procedure::ReplayOperator replay(first.trace());
    runOperator(second, replay, 10000);
    ASSERT_EQ(second.trace().samples.size(), first.trace().samples.size());
    EXPECT_EQ(second.recording().canonicalText(), first.recording().canonicalText());
    EXPECT_FALSE(first.recording().canonicalText().empty());
}

// A HandleLoadSink gets each step's handle load before the step ends (the
// loop's clock has not moved yet: the colon's substeps and the recording are
// still to come), with the values outputs() then holds; and the step is the
// same with a sink as without one, bit for bit.
class EarlyLoads final : public procedure::HandleLoadSink {
public:
    explicit EarlyLoads(const ProcedureLoop& loop) : m_loop(loop) {}
    void handleLoadReady(double handleForce, double handleTorque) override
    {
        times.push_back(m_loop.time());
        forces.push_back(handleForce);
        torques.push_back(handleTorque);
    }
    std::vector<double> times;
    std::vector<double> forces;
    std::vector<double> torques;

private:
    const ProcedureLoop& m_loop;
};

TEST(ProcedureLoop, AHandleLoadSinkIsAnsweredBeforeTheStepEndsWithTheStepsLoad)
{
    ProcedureLoop plain(defaultColon(), ProcedureSettings{});
    ProcedureLoop answered(defaultColon(), ProcedureSettings{});
    EarlyLoads sink(answered);
    procedure::ScriptedOperator novice(procedure::noviceStyle());
    int pushed = 0;
    for (int s = 0; s < 3000; ++s) {
        const InputSample input = novice.next(plain);
        plain.step(input);
        const double before = answered.time();
        answered.step(input, &sink);
        ASSERT_EQ(sink.times.size(), static_cast<size_t>(s) + 1);
        EXPECT_EQ(sink.times.back(), before) << "answered within step " << s;
        EXPECT_LT(sink.times.back(), answered.time());
        EXPECT_EQ(sink.forces.back(), answered.outputs().handleForce) << "step " << s;
        EXPECT_EQ(sink.torques.back(), answered.outputs().handleTorque) << "step " << s;
        pushed += std::abs(sink.forces.back()) > 0.1 ? 1 : 0;
    }
    EXPECT_GT(pushed, 100) << "the novice's push loads the handle";
    EXPECT_EQ(answered.recording().canonicalText(), plain.recording().canonicalText());
}

// NaN and huge device input is refused at the boundary (an input_rejected
// event names the field), the loop keeps the last valid sample, and nothing
// downstream sees the bad value.
TEST(ProcedureLoop, BadDeviceInputIsRejectedAtTheBoundary)
{
    ProcedureLoop loop(defaultColon(), ProcedureSettings{});
    InputSample input;
    RunSummary summary;
    for (int s = 0; s < 600; ++s) {
        input.insertion = 0.05 * s / 600.0;
        InputSample sent = input;
        if (s == 300) {
            sent.insertion = std::numeric_limits<double>::quiet_NaN();
        } else if (s == 301) {
            sent.dialUpDown = 1e9;
        } else if (s == 302) {
            sent.rotation = -std::numeric_limits<double>::infinity();
        }
        loop.step(sent);
        observe(loop, summary);
        if (s >= 300 && s <= 302) {
            EXPECT_TRUE(loop.lastFrame().inputRejected) << s;
            EXPECT_TRUE(std::isfinite(loop.lastFrame().input.insertion));
        }
    }
    EXPECT_TRUE(summary.finite);
    int rejected = 0;
    for (const auto& e : loop.recording().events) {
        rejected += e.kind == procedure::EventKind::InputRejected ? 1 : 0;
    }
    EXPECT_EQ(rejected, 3);
    EXPECT_EQ(loop.trace().samples.size(), 600U) << "the raw input, bad samples included, is in the trace";
}

// Air raises the luminal pressure at insufflator.pressureRate up to
// insufflator.maxPressure and suction lowers it at the same rate; a ceiling
// outside its declared range is refused by name.
TEST(ProcedureLoop, AirAndSuctionMoveThePressureAtTheDeclaredRateUpToTheCeiling)
{
    ProcedureSettings settings;
    settings.insufflator.pressureRate = 1000.0;  // Pa/s
    settings.insufflator.maxPressure = settings.environment.insufflationPressure + 300.0;
    ProcedureLoop loop(defaultColon(), settings);
    const double start = loop.colon().insufflation->pressure();
    InputSample input;
    input.buttons = procedure::kAir;
    for (int s = 0; s < 100; ++s) {
        loop.step(input);
    }
    EXPECT_NEAR(loop.colon().insufflation->pressure(), start + 100.0, 1e-6) << "Pa after 0.1 s of air";
    for (int s = 0; s < 400; ++s) {
        loop.step(input);
    }
    EXPECT_DOUBLE_EQ(loop.colon().insufflation->pressure(), settings.insufflator.maxPressure);
    input.buttons = procedure::kSuction;
    for (int s = 0; s < 200; ++s) {
        loop.step(input);
    }
    EXPECT_NEAR(loop.colon().insufflation->pressure(), settings.insufflator.maxPressure - 200.0, 1e-6);

    settings.insufflator.maxPressure = 20000.0;
    try {
        ProcedureLoop refused(defaultColon(), settings);
        FAIL() << "a 20 kPa ceiling was accepted";
    } catch (const params::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("insufflator.maxPressure"), std::string::npos) << e.what();
    }
}

// The shaft is analysed for loops every loops.analysisInterval (a declared
// parameter): the tip's place along the colon, which each analysis
// measures, changes only on those steps, every 10 ms by default and every
// 20 ms when the interval is set so.
TEST(ProcedureLoop, TheShaftIsAnalysedForLoopsAtTheDeclaredInterval)
{
    for (const double interval : {0.01, 0.02}) {
        ProcedureSettings settings;
        settings.loops.analysisInterval = interval;
        ProcedureLoop loop(defaultColon(), settings);
        const long every = std::lround(interval / settings.stepping.loopStep);
        InputSample input;
        double last = loop.loops().signals().tipArcLength;
        int changes = 0;
        for (long s = 1; s <= 400; ++s) {
            input.insertion = 0.2 * static_cast<double>(s) * settings.stepping.loopStep;  // 20 cm/s
            loop.step(input);
            const double now = loop.loops().signals().tipArcLength;
            if (now != last) {
                ++changes;
                EXPECT_EQ(s % every, 0)
                    << "analysed at step " << s << " with an interval of " << interval << " s";
            }
            last = now;
        }
        EXPECT_GT(changes, 400 / every / 2) << "the tip's place was measured as it went in";
    }
}

// Hard case: full dial deflection while the tip is jammed against the rectal
// wall and the operator keeps pushing at 10 cm/s and twisting. The tissue's
// step check may reject a violent step (a wall node flung faster than
// maxNodeSpeed): it keeps the last good state, refines the substeps and goes
// on; a retry that fails on the same speed is taken (the step resolves that
// motion). Asserted: everything stays finite and bounded, the safeguard
// engages in under 1.5% of the steps (35 of 3,000 measured; 28 before the
// colon touched itself, which changed the path; with the colon touching
// itself but a same-speed retry refused, the colon froze at 1.358 s and
// every later step was refused, 1,642 of them), and each rejection carries
// its diagnostic.
TEST(ProcedureLoop, FullDialsWhileJammedStayStable)
{
    ProcedureLoop loop(defaultColon(), ProcedureSettings{});
    InputSample input;
    RunSummary summary;
    int engaged = 0;  // loop steps in which the tissue's step check rejected a try
    for (int s = 0; s < 3000; ++s) {
        input.insertion = std::min(0.25, 0.1 * s / 1000.0);  // pushes on past the curve at 10 cm/s
        input.dialUpDown = 3.5;                              // beyond the clinical limit: clamped
        input.dialLeftRight = s < 1500 ? 3.5 : -3.5;
        input.rotation = 2.0 * s / 3000.0;  // and twists
        const long triesBefore = loop.tissue().rejectedSteps();
        loop.step(input);
        engaged += loop.tissue().rejectedSteps() > triesBefore ? 1 : 0;
        observe(loop, summary);
    }
    EXPECT_TRUE(summary.finite);
    // A loop step is tried at most twice: count the steps the check engaged in.
    RecordProperty("rejected_tries", std::to_string(loop.tissue().rejectedSteps()));
    RecordProperty("engaged_steps", std::to_string(engaged));
    EXPECT_LT(engaged, 45) << loop.tissue().rejectedSteps() << " tries rejected";
    for (const auto& r : loop.tissue().rejections()) {
        EXPECT_NE(r.message.find("rejected"), std::string::npos);
    }
    EXPECT_LT(summary.peakHandleForce, 50.0);
    // Pressed this hard, the wall bleeds where the scope pushes it: one
    // contact_bleeding event per mark, at the mark's onset.
    EXPECT_GE(loop.bleedingMarks().size(), 1U);
    std::vector<double> bleedingTimes;
    for (const auto& e : loop.recording().events) {
        if (e.kind == procedure::EventKind::ContactBleeding) {
            bleedingTimes.push_back(e.time);
        }
    }
    ASSERT_EQ(bleedingTimes.size(), loop.bleeding().marks().size());
    for (size_t k = 0; k < bleedingTimes.size(); ++k) {
        EXPECT_EQ(bleedingTimes[k], loop.bleeding().marks()[k].onset);
        EXPECT_GE(loop.bleedingMarks()[k].radius, ProcedureSettings{}.bleeding.minRadius);
    }
    EXPECT_EQ(procedure::eventName(procedure::EventKind::ContactBleeding), "contact_bleeding");
}

// A gentle insertion along the straight rectum (2 cm/s, dials centred)
// touches the wall without pressing it: no bleeding mark.
TEST(ProcedureLoop, AGentleStraightInsertionLeavesNoBleedingMark)
{
    ProcedureLoop loop(defaultColon(), ProcedureSettings{});
    InputSample input;
    double peakWallForce = 0.0;
    for (int s = 0; s < 2000; ++s) {
        input.insertion = 0.02 * s / 1000.0;
        loop.step(input);
        peakWallForce = std::max(peakWallForce, loop.lastFrame().maxWallForce);
    }
    EXPECT_GE(loop.scope().numInsertedNodes(), 2) << "the scope went in";
    EXPECT_TRUE(loop.bleedingMarks().empty()) << "peak wall force " << peakWallForce << " N";
}

// How deep the scope's nodes lie in the wall, measured after a step against
// the deformed wall with a tube of its own (not the loop's contact, which
// measures before the step), walking from the anus node by node; and how far
// along the colon the tip is.
struct Penetration {
    double deepest = -1.0;  ///< m, largest depth of a node's surface into the wall
    double tipArc = 0.0;    ///< m along the colon at rest
};

Penetration measurePenetration(const ProcedureLoop& loop, contact::LumenTube& tube, double radius)
{
    Penetration out;
    tube.update(loop.colon().body.positions());
    int section = 0;
    for (const Eigen::Vector3d& p : loop.scope().nodePositions()) {
        const contact::LumenStation at = tube.locate(p, section);
        section = at.ring;
        if (at.beforeStart) {
            continue;  // still outside the anus
        }
        const contact::LumenWallSample wall = tube.wallAt(p, at);
        out.deepest = std::max(out.deepest, wall.distance + radius - wall.wallRadius);
        out.tipArc = tube.arcLength(at);
    }
    return out;
}

// No tunnelling at the top insertion speed. The handle pushes
// straight in at 0.5 m/s with the dials centred and no steering, for 0.5 s
// (25 cm): the tip rams the rectosigmoid flexure head-on and has to bend
// along its wall. After every step no node is ever through the wall (30 mm
// deep would put the scope's axis outside the 16 mm lumen radius plus the
// wall), the tip is carried past the flexure, and over the last 0.1 s of a
// 0.3 s hold the nodes sit within the penalty's depth (median). Not met, and
// in docs/known-limits.md: while the shaft snaps round the flexure a
// node goes up to 25 mm into the wall for tens of milliseconds, and at rest
// the contact still chatters by a few millimetres.
TEST(ProcedureLoop, AFastStraightPushNeverTunnelsThroughTheWall)
{
    constexpr double kSpeed = 0.5;  // m/s
    // m: the snap round the flexure. 2.9 mm with the contact normal's turn
    // taken implicitly (ContactCoupling.h); 13 mm with it re-measured plainly,
    // and 30 mm would put the scope outside the lumen.
    constexpr double kDeepest = 6e-3;
    constexpr double kSettled = 4e-3;  // m: the penalty's depth at tens of newtons
    const ProcedureSettings settings;
    ProcedureLoop loop(defaultColon(), settings);
    contact::LumenTube tube(defaultColon());
    const double radius = 0.5 * settings.scope.outerDiameter;
    InputSample input;
    RunSummary summary;
    double deepest = -1.0;
    double deepestAt = 0.0;
    for (int s = 1; s <= 500; ++s) {
        input.insertion = kSpeed * s * settings.stepping.loopStep;
        loop.step(input);
        observe(loop, summary);
        const Penetration now = measurePenetration(loop, tube, radius);
        if (now.deepest > deepest) {
            deepest = now.deepest;
            deepestAt = loop.time();
        }
    }
    std::vector<double> resting;
    Penetration end;
    for (int s = 0; s < 300; ++s) {
        loop.step(input);
        observe(loop, summary);
        end = measurePenetration(loop, tube, radius);
        if (s >= 200) {
            resting.push_back(end.deepest);
        }
    }
    std::nth_element(resting.begin(), resting.begin() + resting.size() / 2, resting.end());
    const double median = resting[resting.size() / 2];
    EXPECT_TRUE(summary.finite);
    EXPECT_EQ(loop.tissue().rejectedSteps(), 0);
    EXPECT_LT(deepest, kDeepest) << "deepest node " << deepest * 1e3
                                 << " mm into the wall at t = " << deepestAt << " s";
    EXPECT_LT(median, kSettled) << "median depth of the deepest node at rest, mm: " << median * 1e3;
    EXPECT_GT(end.tipArc, 0.15) << "the tip is past the rectosigmoid flexure (m along the colon)";
}

}  // namespace

namespace {

// A colon pressed by a scope that has stopped comes to rest. Before the wall
// springs damped every relative motion of their nodes (transverse damping,
// SpringSet.h), their out-of-plane modes were left with the surrounding drag
// alone and the contact kept them ringing: after this push and a 1 s hold
// the colon still had 2.6-5.3 mJ of kinetic energy, nodes at 1-1.9 m/s, and
// the handle force swung between 0.41 and 1.29 N over the last 0.1 s. With
// it, 2.6 uJ and 1.02-1.11 N: one shaft node's load still flipped between 0.6
// and 0.9 N from step to step, because the contact was measured against the
// wall's present position while the wall node was still moving. Measured
// against the wall carried on by its own velocity over the step, the colon
// is at rest (1e-24 J) and the handle force holds at 1.062 N.
TEST(ProcedureLoop, AColonPressedByAStillScopeComesToRest)
{
    constexpr double kSpeed = 0.5;         // m/s, as in the push above
    constexpr double kRestEnergy = 1e-6;   // J
    constexpr double kForceSpread = 0.01;  // N: handle force range over the last 0.1 s
    const ProcedureSettings settings;
    ProcedureLoop loop(defaultColon(), settings);
    InputSample input;
    for (int s = 1; s <= 500; ++s) {
        input.insertion = kSpeed * s * settings.stepping.loopStep;
        loop.step(input);
    }
    double peakEnergy = 0.0;  // J over the last 0.1 s
    double lowForce = std::numeric_limits<double>::infinity();
    double highForce = -lowForce;
    for (int s = 0; s < 1000; ++s) {
        loop.step(input);
        if (s < 900) {
            continue;
        }
        const physics::TissueBody& body = loop.colon().body;
        double energy = 0.0;
        for (Eigen::Index i = 0; i < body.velocities().cols(); ++i) {
            energy += 0.5 * body.masses()[i] * body.velocities().col(i).squaredNorm();
        }
        peakEnergy = std::max(peakEnergy, energy);
        lowForce = std::min(lowForce, loop.outputs().handleForce);
        highForce = std::max(highForce, loop.outputs().handleForce);
    }
    EXPECT_LT(peakEnergy, kRestEnergy)
        << "J of kinetic energy left in the colon 0.9-1 s after the scope stopped";
    EXPECT_LT(highForce - lowForce, kForceSpread)
        << "handle force between " << lowForce << " and " << highForce << " N";
    EXPECT_GT(lowForce, 0.0) << "the scope still presses on the wall";
}

}  // namespace

namespace {

// The contact is solved once per step, or again on the shape the chain found
// until the loads settle, at most contact.couplingPasses times; a count
// outside its range is refused with the parameter's name.
TEST(ProcedureLoop, TheContactIsSolvedAtMostCouplingPassesTimesPerStep)
{
    // Every solve sweeping to contact.sweepTolerance, a step stops once its
    // loads settle (the default); with a looser contact.passSweepTolerance
    // for the solves another follows, every step runs all its passes and its
    // last solve sweeps to contact.sweepTolerance.
    for (const bool loose : {false, true}) {
        for (const double passes : {1.0, 3.0}) {
            ProcedureSettings settings;
            settings.contact.couplingPasses = passes;
            settings.contact.passSweepTolerance = loose ? 3e-3 : settings.contact.sweepTolerance;
            ASSERT_EQ(loose, settings.contact.passSweepTolerance > settings.contact.sweepTolerance);
            ProcedureLoop loop(defaultColon(), settings);
            InputSample input;
            int fewest = 100;
            int most = 0;
            int unsettled = 0;
            for (int s = 1; s <= 500; ++s) {
                input.insertion = 0.5 * s * settings.stepping.loopStep;  // the 0.5 m/s push above
                loop.step(input);
                fewest = std::min(fewest, loop.couplingPasses());
                most = std::max(most, loop.couplingPasses());
                const auto& coupling = loop.coupling();
                if (coupling.residual() >= settings.contact.sweepTolerance &&
                    coupling.sweeps() < settings.contact.couplingSweeps) {
                    ++unsettled;
                }
            }
            EXPECT_GE(fewest, 1) << passes;
            EXPECT_EQ(most, static_cast<int>(passes))
                << "the shaft against the flexure takes every pass allowed";
            EXPECT_EQ(unsettled, 0) << "a step's last solve sweeps to contact.sweepTolerance or to the cap";
            if (passes > 1.0) {
                if (loose) {
                    EXPECT_EQ(fewest, most) << "with looser passes every step runs them all";
                } else {
                    EXPECT_LT(fewest, most) << "a step whose loads settle at once stops early";
                }
            }
        }
    }
    ProcedureSettings bad;
    bad.contact.couplingPasses = 0.0;
    try {
        ProcedureLoop loop(defaultColon(), bad);
        ADD_FAILURE() << "0 passes accepted";
    } catch (const params::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("contact.couplingPasses"), std::string::npos) << e.what();
    }
}

// The prefix sweeps (contact.prefixSweeps) solve the same contact as the
// dense ones, rounded differently: a 0.5 m/s push against the rectosigmoid
// flexure (contact loads up to 5.6 N) ends with the same tip and handle force
// to within what that rounding grows to over its 400 steps.
TEST(ProcedureLoop, PrefixSweepsFollowTheDenseSweeps)
{
    const auto push = [](double prefixSweeps, double elementPoints, double sideNormals) {
        ProcedureSettings settings;
        settings.contact.prefixSweeps = prefixSweeps;
        settings.contact.elementPoints = elementPoints;
        settings.contact.sideNormals = sideNormals;
        ProcedureLoop loop(defaultColon(), settings);
        InputSample input;
        double loaded = 0.0;
        for (int s = 1; s <= 400; ++s) {
            input.insertion = 0.5 * s * settings.stepping.loopStep;
            loop.step(input);
            loaded = std::max(loaded, loop.coupling().loads().colwise().norm().maxCoeff());
        }
        return std::tuple{loop.scope().tipPose().position, loop.outputs().handleForce, loaded};
    };
    // Also with a contact point inside each element (contact.elementPoints),
    // whose prefix sums are those of the joints that move it, and with the
    // loads pushed across the shaft (contact.sideNormals).
    for (const auto& [points, side] : {std::pair{0.0, 0.0}, std::pair{1.0, 0.0}, std::pair{1.0, 1.0}}) {
        const auto [denseTip, denseForce, denseLoad] = push(0.0, points, side);
        const auto [prefixTip, prefixForce, prefixLoad] = push(1.0, points, side);
        EXPECT_GT(denseLoad, 0.5) << "the shaft is in contact";
        EXPECT_NEAR(prefixLoad, denseLoad, 1e-9) << points;
        EXPECT_LT((prefixTip - denseTip).norm(), 1e-9) << points;  // m; 5e-17 when measured
        EXPECT_NEAR(prefixForce, denseForce, 1e-9) << points;      // N
    }
}

// Contact points inside the elements (contact.elementPoints) hold the
// elements, not only the nodes, off the wall: a blind 0.5 m/s push round the
// rectosigmoid flexure, with every element's midpoint measured against the
// lumen on its own every 10 ms. With the nodes alone (21.5 mm apart) an
// element's middle goes several millimetres into the wall that its nodes
// rest on; with one contact point inside each element, no further than a
// node does.
TEST(ProcedureLoop, ElementPointsHoldTheElementsOffTheWall)
{
    const auto push = [](double elementPoints) {
        ProcedureSettings settings;
        settings.contact.elementPoints = elementPoints;
        ProcedureLoop loop(defaultColon(), settings);
        contact::LumenContact midpoints(defaultColon(), settings.contact);
        InputSample input;
        double deepest = 0.0;
        double loaded = 0.0;
        for (int s = 1; s <= 600; ++s) {
            input.insertion = 0.5 * s * settings.stepping.loopStep;
            loop.step(input);
            loaded = std::max(loaded, loop.coupling().loads().colwise().norm().maxCoeff());
            if (s % 10 != 0) {
                continue;
            }
            const auto nodes = loop.scope().nodePositions();
            Eigen::Matrix3Xd mid(3, static_cast<Eigen::Index>(nodes.size()) - 1);
            for (Eigen::Index i = 0; i < mid.cols(); ++i) {
                mid.col(i) = 0.5 * (nodes[static_cast<size_t>(i)] + nodes[static_cast<size_t>(i) + 1]);
            }
            const Eigen::Matrix3Xd& wall = loop.colon().body.positions();
            const auto& measured = midpoints.compute(mid, Eigen::Matrix3Xd::Zero(3, mid.cols()),
                                                     0.5 * settings.scope.outerDiameter, wall,
                                                     Eigen::Matrix3Xd::Zero(3, wall.cols()));
            for (const auto& c : measured) {
                deepest = std::max(deepest, c.depth);
            }
        }
        return std::pair{deepest, loaded};
    };
    const auto [nodesDeepest, nodesLoaded] = push(0.0);
    const auto [pointsDeepest, pointsLoaded] = push(1.0);
    RecordProperty("midpoint_depth_nodes_mm", std::to_string(nodesDeepest * 1e3));
    RecordProperty("midpoint_depth_points_mm", std::to_string(pointsDeepest * 1e3));
    EXPECT_GT(nodesLoaded, 0.5) << "the shaft is pressed on the wall";
    EXPECT_GT(pointsLoaded, 0.5);
    // Measured: 5.85 mm with the nodes alone, 0.45 mm with the points.
    EXPECT_GT(nodesDeepest, 3e-3) << "with the nodes alone an element's middle goes into the wall";
    EXPECT_LT(pointsDeepest, 1.5e-3) << "about as far as a node goes in this push (1.16 mm)";
}

// The contact solve's sweep limits are declared parameters: values outside
// their ranges are refused by name before the loop starts.
TEST(ProcedureLoop, SweepLimitsOutsideTheirRangeAreRefusedByName)
{
    ProcedureSettings sweeps;
    sweeps.contact.couplingSweeps = 0.0;
    ProcedureSettings tolerance;
    tolerance.contact.sweepTolerance = 1.0;
    ProcedureSettings passTolerance;
    passTolerance.contact.passSweepTolerance = 1.0;
    ProcedureSettings prefix;
    prefix.contact.prefixSweeps = 2.0;
    ProcedureSettings acceleration;
    acceleration.contact.sweepAcceleration = 11.0;
    ProcedureSettings points;
    points.contact.elementPoints = 4.0;
    ProcedureSettings side;
    side.contact.sideNormals = 2.0;
    ProcedureSettings pleats;
    pleats.contact.pleatSearch = -1.0;
    for (const auto& [settings, name] :
         {std::pair{sweeps, "contact.couplingSweeps"}, std::pair{tolerance, "contact.sweepTolerance"},
          std::pair{passTolerance, "contact.passSweepTolerance"}, std::pair{prefix, "contact.prefixSweeps"},
          std::pair{points, "contact.elementPoints"}, std::pair{side, "contact.sideNormals"},
          std::pair{pleats, "contact.pleatSearch"}, std::pair{acceleration, "contact.sweepAcceleration"}}) {
        try {
            ProcedureLoop loop(defaultColon(), settings);
            ADD_FAILURE() << name << " accepted";
        } catch (const params::ParameterError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

}  // namespace

// reference/clinical-assessment.md: loops are reduced by withdrawing with
// clockwise torque, but a reverse alpha needs counter-clockwise torque.
TEST(ScriptedOperator, ReducesEveryLoopClockwiseButAReverseAlphaCounterClockwise)
{
    using procedure::LoopKind;
    for (const LoopKind kind : {LoopKind::None, LoopKind::N, LoopKind::Alpha, LoopKind::GammaDeepTransverse,
                                LoopKind::ReverseSplenic}) {
        EXPECT_EQ(procedure::reductionTurn(kind), -1.0) << procedure::loopName(kind);
    }
    EXPECT_EQ(procedure::reductionTurn(LoopKind::ReverseAlpha), 1.0);
}

namespace {

/// What the handle feels while the shaft is turned on the wall: the mean
/// axial torque and mu r times the mean sum of the normal loads (the
/// friction moment of every contact sliding), over the last half second of
/// a turn at `rate` rad/s held for one second, the scope 25 cm in.
struct TurnedShaft {
    double handleTorque = 0.0;    ///< N m, counter-clockwise seen from the operator
    double slidingMoment = 0.0;   ///< mu r sum lambda, N m
    double largestTipStep = 0.0;  ///< m, while the shaft is turned
};

TurnedShaft turnOnTheWall(bool spinFriction, double rate)
{
    ProcedureSettings settings;
    settings.contact.stickingFriction = 1.0;
    settings.contact.spinFriction = spinFriction ? 1.0 : 0.0;
    ProcedureLoop loop(defaultColon(), settings);
    const double mu = settings.contact.frictionCoefficient;
    const double radius = 0.5 * settings.scope.outerDiameter;
    InputSample input;
    TurnedShaft out;
    int measured = 0;
    Eigen::Vector3d tip = Eigen::Vector3d::Zero();
    for (int s = 0; s < 6500; ++s) {
        input.insertion = std::min(0.25, 0.05 * s / 1000.0);  // 5 cm/s to 25 cm, then held
        input.rotation = s < 5500 ? 0.0 : rate * (s - 5500) / 1000.0;
        loop.step(input);
        const Eigen::Vector3d now = loop.outputs().tip.position;
        if (s > 5500) {
            out.largestTipStep = std::max(out.largestTipStep, (now - tip).norm());
        }
        tip = now;
        if (s >= 6000) {
            double loads = 0.0;
            for (const Eigen::Vector3d& load : loop.coupling().normalLoads()) {
                loads += load.norm();
            }
            out.handleTorque += loop.outputs().handleTorque;
            out.slidingMoment += mu * radius * loads;
            ++measured;
        }
    }
    out.handleTorque /= measured;
    out.slidingMoment /= measured;
    return out;
}

}  // namespace

// Spin friction at the handle: the scope 25 cm into the default colon, its
// shaft lying on the wall of the rectum and the rectosigmoid, turned
// counter-clockwise at 2 rad/s. With spin friction the wall resists the turn
// with the friction moment of the contacts sliding round, mu r sum lambda at
// most: the handle feels it clockwise (negative), on top of what it feels
// without. Without spin friction nothing resists the turn but the moments of
// the contact forces about the anus.
TEST(ProcedureLoop, SpinFrictionResistsTheShaftTurningOnTheWall)
{
    const double rate = 2.0;  // rad/s
    const TurnedShaft plain = turnOnTheWall(false, rate);
    const TurnedShaft spun = turnOnTheWall(true, rate);
    RecordProperty("handle_torque_without_Nm", std::to_string(plain.handleTorque));
    RecordProperty("handle_torque_with_Nm", std::to_string(spun.handleTorque));
    RecordProperty("sliding_moment_Nm", std::to_string(spun.slidingMoment));
    RecordProperty("largest_tip_step_without_m", std::to_string(plain.largestTipStep));
    RecordProperty("largest_tip_step_with_m", std::to_string(spun.largestTipStep));
    ASSERT_GT(spun.slidingMoment, 0.0) << "the shaft lies on the wall";
    const double resisted = plain.handleTorque - spun.handleTorque;
    EXPECT_GT(resisted, 0.5 * spun.slidingMoment);
    EXPECT_LT(resisted, 1.2 * spun.slidingMoment);
    EXPECT_LT(spun.largestTipStep, 2e-3) << "the turn stays smooth";
}

namespace {

// Scoring's geometric mucosa estimate spans the case's colon: the loop gives
// the anatomy's centreline length, not the settings' default.
TEST(ProcedureLoop, TheColonLengthIsTheAnatomysWhateverTheSettingsSay)
{
    geometry::AnatomyParameters shorter;
    shorter.transverseLength = geometry::AnatomyParameters::transverseLengthSpec.minValue;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(shorter);
    const procedure::ProcedureSettings settings;
    const procedure::ProcedureLoop loop(anatomy, settings);
    EXPECT_DOUBLE_EQ(loop.colonLength(), anatomy.centreline.length());
    EXPECT_LT(loop.colonLength(), settings.recorder.colonLength - 0.05)
        << "a shorter transverse colon than the default's";
}

}  // namespace
