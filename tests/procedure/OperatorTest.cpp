// The scripted expert on the default colon. Aiming with the left/right dial
// alone, it curled its tip at the sigmoid-descending junction (the dial at
// its stop, the lumen still off centre) and never fed again: the tip stayed
// at or before 0.478 m along the colon for the whole 60 s. With torque
// steering, its ways past a bend it cannot aim through, the loop rule and
// the aiming behind its tip, this test once held it past the splenic
// flexure within a minute (1.02 m at 60 s). That pass was not mechanics:
// the colon had no contact with itself, the scope pushed the sigmoid into a
// hairpin whose two limbs passed into each other (ring centres 21 mm apart
// with lumen radii of 14 mm), and the tip crossed from one limb into the
// other. With the lumen's self-contact (physics/LumenSelfContact.h) the
// limbs stay apart, and the expert, which is kept inside the lumen up to the
// junction, comes within 8 cm of it in 20 s. Measured: 0.512 m with the tip
// at most 6.3 mm into the wall while the wall springs were damped along
// their length only (the wall rang under the contact, nodes at up to
// 13 m/s); 0.479 m and 4.1 mm once they damp every relative motion
// (SpringSet.h): the expert now meets the sigmoid's last bend at 16.5 s with
// its up/down dial at the stop and pulls back at 18.5 s. It passed the
// junction at 44.75 s and from 48 s its tip was driven out through the
// descending colon's wall, the shaft swinging 10-20 mm a step; with the
// contact loads relaxed and friction's stick taken from all the contacts
// together (procedure/ContactCoupling.h) it passes the junction at about
// 40 s and reaches 0.48 m in 20 s with the tip at most 2.6 mm in. The
// transverse colon, reached by 50 s, is beyond this test's 45 s; the
// cecum is the next test's.

#include "simcore/procedure/Operator.h"
#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

using namespace colonosim;

// Stays inside: over 45 s the expert presses on the junction for 25 s with
// its dial at the stop. Solving the contact once per step (the coupling's
// model linear about the step's start shape) its tip was more than a scope
// diameter into the wall for 74 steps by 45 s (18.4 mm deep), and went
// through it by 50 s; with the contact re-solved on the shape the chain
// found (contact.couplingPasses = 3) for none (8.5 mm at most); with the
// loads relaxed (contact.loadRelaxation) for 11 (15.5 mm at most, at
// 40-45 s, as the tip passes into the descending colon). And it passes the
// junction: after 3 s without getting on it pulls back even with its dials
// short of their stops. Without that rule it stood still at the junction
// (0.537 m) from 40 s on, holding 3.8 N.
TEST(ExpertOperator, ReachesTheSigmoidDescendingJunctionInTwentySecondsAndPassesItInsideTheLumen)
{
    constexpr int kSteps = 45000;      // 45 s at 1 kHz
    constexpr int kApproach = 20000;   // 20 s
    constexpr int kStepsOutside = 50;  // 50 ms with the tip more than a scope diameter in
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureSettings settings;
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const geometry::Centreline& colon = loop.loops().colon();
    double descendingStart = colon.length();  // m along the colon
    for (double s = 0.0; s < colon.length(); s += 0.005) {
        if (geometry::sampleCentreline(colon, s).segment == geometry::Segment::Descending) {
            descendingStart = s;
            break;
        }
    }
    ASSERT_LT(descendingStart, colon.length());
    const double diameter = settings.scope.outerDiameter;
    double furthest = 0.0;        // m along the colon within the approach
    double reached = 0.0;         // m along the colon within the whole run
    double approachDepth = -1.0;  // deepest the tip went into the wall within the approach, m
    int outside = 0;              // steps with the tip more than a scope diameter in
    int steps = 0;
    for (; steps < kSteps && !expert.finished(); ++steps) {
        loop.step(expert.next(loop));
        const double depth = loop.lumen().contacts().back().depth;
        outside += depth > diameter ? 1 : 0;
        reached = std::max(reached, loop.lastFrame().tipArcLength);
        if (steps < kApproach) {
            furthest = std::max(furthest, loop.lastFrame().tipArcLength);
            approachDepth = std::max(approachDepth, depth);
        }
    }
    RecordProperty("furthest_m", std::to_string(furthest));
    RecordProperty("approach_tip_depth_mm", std::to_string(approachDepth * 1e3));
    RecordProperty("steps_outside", std::to_string(outside));
    EXPECT_EQ(steps, kSteps) << "the expert is still at work";
    EXPECT_GT(furthest, 0.47) << "within 8.5 cm of the descending colon's start (" << descendingStart
                              << " m) in 20 s";
    EXPECT_LT(approachDepth, diameter) << "the tip stayed inside the wall's surface up to 20 s";
    EXPECT_LT(outside, kStepsOutside)
        << "steps with the tip more than a scope diameter into the wall in 45 s";
    EXPECT_GT(reached, descendingStart) << "the tip passed into the descending colon within 45 s";
}

// The cecum. Backing off at 8 N of felt handle force, the expert passed the
// splenic flexure (0.89 m at 50 s) and then backed off, re-inserted and
// backed off again at 0.74-0.78 m of insertion until at least 150 s, its tip
// at 0.83-0.85 m: pushing bowed the sigmoid, which took 9-11 N of the push,
// and the tip went back round the flexure. With 12 N allowed once the tip
// had reached the flexure the shaft gave at 56 s, the tip came back into the
// descending colon and then followed the shaft 1:1 into the transverse
// colon, and on to the cecum; 12 N is now allowed from the descending colon
// on (expertStyle()). (The way back is not yet whole: see
// docs/known-limits.md.)
TEST(ExpertOperator, ReachesTheCecumOfTheDefaultColonWithItsTipInsideTheLumen)
{
    constexpr int kMaxSteps = 150000;  // 150 s at 1 kHz
    constexpr int kStepsOutside = 50;  // 50 ms with the tip more than a scope diameter in
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureSettings settings;
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const double diameter = settings.scope.outerDiameter;
    const auto& events = loop.recording().events;
    const auto cecumReached = [&events] {
        return std::any_of(events.begin(), events.end(), [](const procedure::RecordedEvent& e) {
            return e.kind == procedure::EventKind::CecumReached;
        });
    };
    int outside = 0;         // steps with the tip more than a scope diameter in
    double deepest = 0.0;    // m
    double peakForce = 0.0;  // N at the handle
    for (int steps = 0; steps < kMaxSteps && !cecumReached(); ++steps) {
        loop.step(expert.next(loop));
        const double depth = loop.lumen().contacts().back().depth;
        outside += depth > diameter ? 1 : 0;
        deepest = std::max(deepest, depth);
        peakForce = std::max(peakForce, std::abs(loop.outputs().handleForce));
    }
    const bool perforated = std::any_of(events.begin(), events.end(), [](const procedure::RecordedEvent& e) {
        return e.kind == procedure::EventKind::Perforation;
    });
    RecordProperty("cecum_s", std::to_string(loop.time()));
    RecordProperty("insertion_m", std::to_string(loop.trace().samples.back().insertion));
    RecordProperty("steps_outside", std::to_string(outside));
    RecordProperty("deepest_mm", std::to_string(deepest * 1e3));
    RecordProperty("peak_handle_force_N", std::to_string(peakForce));
    ASSERT_TRUE(cecumReached()) << "the tip is at " << loop.lastFrame().tipArcLength << " m of "
                                << loop.loops().colon().length() << " m after " << loop.time() << " s";
    EXPECT_LT(outside, kStepsOutside) << "steps with the tip more than a scope diameter into the wall";
    EXPECT_FALSE(perforated);
}

// Generated patient 5 (a 1.19 m colon). With its tip just past the
// sigmoid-descending junction, 0.40 m along the colon, one contact point of
// the shaft 2 cm behind the tip bore 4-9 N with the wall's normal within
// 40 degrees of the shaft's axis, and the expert, backing off at 8 N, went
// back 3 cm and came up to the same place every 3 s: 0.432 m along the
// colon at most in 150 s. With 12 N allowed once its tip has reached the
// descending colon (expertStyle(); the shaft lies through the whole sigmoid
// from there) it passes the junction and reaches the cecum in under a
// minute, inside the lumen.
TEST(ExpertOperator, PassesTheSigmoidDescendingJunctionOfGeneratedPatientFiveAndReachesItsCecum)
{
    constexpr int kMaxSteps = 60000;      // 60 s at 1 kHz
    constexpr int kStepsOutside = 50;     // 50 ms with the tip more than a scope diameter in
    constexpr double kForceLimit = 25.0;  // N: the haptic device's limit
    const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(5));
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    const procedure::ProcedureSettings settings = cases::procedureSettings(scene);
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const double diameter = settings.scope.outerDiameter;
    int outside = 0;
    double peakForce = 0.0;  // N at the handle
    for (int steps = 0; steps < kMaxSteps && !loop.cecumReached(); ++steps) {
        loop.step(expert.next(loop));
        outside += loop.lumen().contacts().back().depth > diameter ? 1 : 0;
        peakForce = std::max(peakForce, std::abs(loop.outputs().handleForce));
    }
    RecordProperty("cecum_s", std::to_string(loop.time()));
    RecordProperty("steps_outside", std::to_string(outside));
    RecordProperty("peak_handle_force_N", std::to_string(peakForce));
    ASSERT_TRUE(loop.cecumReached()) << "the tip is at " << loop.lastFrame().tipArcLength << " m of "
                                     << loop.loops().colon().length() << " m after " << loop.time() << " s";
    EXPECT_LT(outside, kStepsOutside) << "steps with the tip more than a scope diameter into the wall";
    EXPECT_LT(peakForce, kForceLimit);
}

// Generated patient 2 as the core curriculum draws its cases (colons no
// longer than the scope): reducing a loop at 1.25 m, the expert used to draw
// the shaft back against a colon that held it, pulling 52 N at the handle
// for seconds (6,421 steps over 20 N) and reaching the cecum at 121.8 s
// with 35.9 s looped. Drawing back only while the pull it feels stays under
// its force limit, and giving a held back-off up after 3 s, it reaches the
// cecum at 75.6 s, with 18.0 s looped and 13.4 N at most.
TEST(ExpertOperator, DrawsTheShaftBackOnlyWhileThePullStaysUnderItsLimit)
{
    constexpr int kMaxSteps = 90000;      // 90 s at 1 kHz
    constexpr double kForceLimit = 25.0;  // N: the haptic device's limit
    constexpr double kHardPull = 20.0;    // N of pull no expert holds
    constexpr int kHardPullSteps = 50;    // 50 ms of it at most
    cases::Constraints curriculum;
    curriculum.require = cases::RequireExpression::parse("colon_length<=170");
    const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(2, curriculum));
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    procedure::ProcedureLoop loop(anatomy, cases::procedureSettings(scene));
    procedure::ScriptedOperator expert(procedure::expertStyle());
    double peakForce = 0.0;  // N at the handle, either way
    int hardPulls = 0;       // steps pulling harder than kHardPull
    for (int steps = 0; steps < kMaxSteps && !loop.cecumReached(); ++steps) {
        loop.step(expert.next(loop));
        const double force = loop.outputs().handleForce;  // + resists insertion, - withdrawal
        peakForce = std::max(peakForce, std::abs(force));
        hardPulls += -force > kHardPull ? 1 : 0;
    }
    RecordProperty("cecum_s", std::to_string(loop.time()));
    RecordProperty("peak_handle_force_N", std::to_string(peakForce));
    RecordProperty("steps_pulling_over_20N", std::to_string(hardPulls));
    ASSERT_TRUE(loop.cecumReached()) << "the tip is at " << loop.lastFrame().tipArcLength << " m of "
                                     << loop.loops().colon().length() << " m after " << loop.time() << " s";
    EXPECT_LT(hardPulls, kHardPullSteps);
    EXPECT_LT(peakForce, kForceLimit);
}

}  // namespace
