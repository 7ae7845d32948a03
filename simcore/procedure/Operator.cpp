#include "simcore/procedure/Operator.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <algorithm>
#include <cmath>

namespace colonosim::procedure {

namespace {

/// rad: the furthest the scripted hands turn either dial (short of the
/// scope's stops, as a person leaves a margin on the wheel).
constexpr double kDialStop = 2.5;
/// rad: the furthest the up/down dial is turned; it reaches further than
/// the left/right one (180 against 160 degrees on the scope), which is why
/// experts steer with up/down and shaft torque.
constexpr double kUpDownStop = 3.0;
/// 1/s: rate at which shaft torque hands a left/right deflection over to the
/// up/down dial (torque steering: turn the shaft, keep the tip's bend where
/// it points, and let the up/down wheel hold it).
constexpr double kTorqueSteering = 1.0;
/// rad: a dial this close to kDialStop counts as at its stop (the hand
/// feels the wheel stiffen).
constexpr double kNearStop = 0.05;
/// s a dial stays at its stop without the scope getting on before the
/// expert changes approach (a moment's look, not a fight).
constexpr double kBlockedFor = 1.5;
/// m fed within kBlockedFor that still counts as getting on.
constexpr double kBlockedFeed = 0.005;
/// m of the scope's working length a hand keeps outside the anus, holding
/// the shaft (the scripted operators insert at most the working length less this).
constexpr double kHeldOutside = 0.05;
/// m of insertion at which the withdrawal ends: the tip back in the rectum,
/// the examination over.
constexpr double kWithdrawnTo = 0.05;
/// s without getting on (kBlockedFeed) while inserting or sliding by, the
/// dials short of their stops, before the expert changes approach all the
/// same: a hand that neither feeds nor turns further is stuck (at the
/// sigmoid-descending junction it held 3.8 N, above kSlideForce, with the
/// up/down dial at 2.45 rad, and stood still for 20 s).
constexpr double kStillFor = 3.0;
/// m withdrawn to straighten the sigmoid and give the bending section room
/// before re-aiming ("pull back and re-approach").
constexpr double kPullBackLength = 0.04;
/// 1/s: rate at which the dials are let go while pulling back, so the tip
/// unhooks from the bend and is aimed afresh on the way in.
constexpr double kUnhookRate = 1.0;
/// rad: the expert withdraws only once the dials are let go below this, so
/// a hooked tip does not drag the wall (straighten the tip, then pull).
constexpr double kUnhooked = 1.0;
/// pull-backs tried at one bend before sliding by it.
constexpr int kPullBacksPerBend = 1;
/// m the tip must have gone past a bend for the next block to count as a
/// new bend (and its pull-backs to start again).
constexpr double kNewBend = 0.05;
/// m/s: the slow feed of a slide-by, the tip deflected towards the lumen
/// gliding along the wall (a third of the expert's usual pace).
constexpr double kSlideSpeed = 0.01;
/// N: a slide-by feeds only below this handle force (an expert slides
/// by with a light touch, well under the back-off limit).
constexpr double kSlideForce = 3.0;
/// m fed in one slide-by before giving up on it and pulling back again.
constexpr double kSlideLength = 0.06;
/// m withdrawn in one loop reduction (the standard 3 cm back-off).
constexpr double kReduceLength = 0.03;
/// m withdrawn at most in one loop reduction while the loop persists.
constexpr double kReduceAtMost = 0.15;
/// insertion advance over tip advance above which the tip no longer follows
/// the shaft (the clinical warning sign of a loop: not 1:1).
constexpr double kTipLags = 2.0;
/// loop reductions begun at one place (within kNewBend of each other along
/// the colon) before the expert stops reducing the loop there and pushes on
/// through it: a redundant sigmoid reloops as soon as the scope advances, and
/// the technique then is to let the loop form, reach the colon beyond it and
/// reduce it from there with the tip hooked (clinical-assessment.md,
/// "Reduction"; the alpha manoeuvre).
constexpr int kReductionsPerPlace = 2;
/// m the tip goes on along the colon through a loop it has let be before
/// the expert reduces loops again (past the sigmoid's far limb, into the
/// colon beyond it, where the tip can be hooked).
constexpr double kPassLoopLength = 0.15;
/// s a back-off holds a pull above the force limit before the expert gives
/// it up and goes on in (the same moment's look as kStillFor): drawing the
/// shaft back against a colon that holds it only drags the colon with it
/// (on generated patient 2, drawn as the core curriculum draws, reducing a
/// loop at 1.25 m pulled with 52 N for seconds).
constexpr double kPullHeldFor = 3.0;

}  // namespace

double reductionTurn(LoopKind kind)
{
    return kind == LoopKind::ReverseAlpha ? 1.0 : -1.0;
}

/// The expert backs off at 8 N of felt handle force while its tip is in the
/// rectum or the sigmoid and at 12 N once the tip has reached the descending
/// colon. From there on the shaft lies through the whole sigmoid, and the
/// sigmoid resists the push: on the default colon, at 55 s, the contact
/// loads' components along the shaft summed to 9-11 N in the sigmoid against
/// 7-8 N of handle force, and at 8 N the expert backed off, re-inserted and
/// backed off again at 0.74-0.78 m of insertion from 50 s to 150 s. On
/// generated patients 1 and 5, with the tip just past the sigmoid-descending
/// junction, one contact point 2 cm behind the tip bore 4-9 N against the
/// shaft (the wall's normal within 40 degrees of its axis), and at 8 N the expert
/// backed off 3 cm and came back to the same place every 3 s for the whole
/// run. 12 N is within what operators apply: they exceed 10 N about 5% of the
/// time, with peaks of 43 N (Appleyard et al., Gastrointest Endosc 2000). The
/// 8 N limit is kept in the sigmoid: 9 N or 12 N from the start pushed the
/// tip of generated patient 1 out through its sigmoid (176 steps more than a
/// scope diameter into the wall by 20 s, none at 8 N).
OperatorStyle expertStyle()
{
    return {0.03, 0.01, 8.0, 12.0, true, 2.0, 0.5, true, 0.1, 0.5, true};
}

OperatorStyle noviceStyle()
{
    return {0.06, 0.04, 25.0, 25.0, false, 0.5, 3.0};
}

bool LoopReductionCount::reduceAt(double tipArc)
{
    if (m_reducedAt >= 0.0 && std::abs(tipArc - m_reducedAt) < m_samePlace) {
        ++m_here;
    } else {
        m_reducedAt = tipArc;
        m_here = 1;
    }
    if (m_here <= m_perPlace) {
        return true;
    }
    m_passUntil = tipArc + m_passLength;
    m_here = 0;
    m_reducedAt = -1.0;
    return false;
}

ScriptedOperator::ScriptedOperator(const OperatorStyle& style)
    : m_style(style), m_reductions(kReductionsPerPlace, kNewBend, kPassLoopLength)
{
    m_inViewSince.fill(-1.0);
}

InputSample ScriptedOperator::next(const ProcedureLoop& loop)
{
    const double dt = loop.trace().loopStep;
    const ProcedureFrame& frame = loop.lastFrame();
    const double raw = loop.outputs().handleForce;
    m_feltForce = m_style.feelTime > 0.0
                      ? m_feltForce + std::min(1.0, dt / m_style.feelTime) * (raw - m_feltForce)
                      : raw;
    const double force = m_feltForce;
    m_pastSigmoid = m_pastSigmoid || frame.tipSegment >= geometry::Segment::Descending;
    const double forceLimit = m_pastSigmoid ? m_style.pastSigmoidForceLimit : m_style.forceLimit;
    const double maxInsertion = loop.scope().parameters().workingLength - kHeldOutside;

    // The lumen as the camera sees it: the deformed lumen's centre 4 cm
    // ahead of the tip, in the tip's frame (x = the viewer's left, y = up,
    // z = forward; see TipPose).
    Eigen::Vector3d target = frame.tipPosition;
    if (!loop.lumen().contacts().empty()) {
        const contact::LumenStation& at = loop.lumen().contacts().back().station;
        target = loop.lumen().tube().centreAlong(at, m_phase == Phase::Withdraw ? -0.04 : 0.04);
    }
    const Eigen::Vector3d inCamera = loop.outputs().tip.rotation.transpose() * (target - frame.tipPosition);
    if (inCamera.norm() > 1e-6 && m_phase != Phase::Withdraw) {
        // Turn the dials towards the lumen, following its angular offset with
        // a first-order lag (the operator's reaction), within +-1 rad.
        // The angle between the view's axis and the lumen (0 ahead, pi
        // behind the tip), split along the direction the lumen lies in: a
        // lumen behind a folded-back tip needs more bend, not a mirror of the
        // bend it has.
        const double aside = std::hypot(inCamera.x(), inCamera.y());
        const double angle = std::atan2(aside, inCamera.z());
        double up = aside > 1e-9 ? angle * inCamera.y() / aside : 0.0;
        double left = aside > 1e-9 ? angle * inCamera.x() / aside : 0.0;
        const double follow = std::min(1.0, m_style.steeringGain * dt);
        if (m_style.aimsBeforeInserting) {
            if (m_phase != Phase::Insert && m_phase != Phase::SlideBy) {
                up = 0.0;
                left = 0.0;
            }
            // Turn the dials while the lumen is off centre and hold them where it is centred.
            m_input.dialUpDown = std::clamp(m_input.dialUpDown + follow * up, -kUpDownStop, kUpDownStop);
            m_input.dialLeftRight = std::clamp(m_input.dialLeftRight + follow * left, -kDialStop, kDialStop);
            if (m_phase == Phase::Insert || m_phase == Phase::SlideBy) {
                // Torque steering: turn the shaft by dTurn (about the viewing
                // direction, clockwise seen from the operator: the input's
                // rotation is counter-clockwise, so it takes -dTurn) and
                // counter-turn the deflection in the tip's frame, so the bend
                // keeps pointing where it does while it moves onto the up/down dial.
                const double turn = -kTorqueSteering * m_input.dialLeftRight * dt;
                const double c = std::cos(turn);
                const double s = std::sin(turn);
                const double lr = c * m_input.dialLeftRight + s * m_input.dialUpDown;
                const double ud = -s * m_input.dialLeftRight + c * m_input.dialUpDown;
                m_input.rotation -= turn;
                m_input.dialLeftRight = std::clamp(lr, -kDialStop, kDialStop);
                m_input.dialUpDown = std::clamp(ud, -kUpDownStop, kUpDownStop);
            }
            m_offCentre = std::hypot(up, left);
        } else {
            m_input.dialUpDown += follow * (std::clamp(up, -1.0, 1.0) - m_input.dialUpDown);
            m_input.dialLeftRight += follow * (std::clamp(left, -1.0, 1.0) - m_input.dialLeftRight);
        }
    } else {
        m_input.dialUpDown *= 1.0 - dt;  // relax the dials while withdrawing
        m_input.dialLeftRight *= 1.0 - dt;
    }

    // Lesions: mark each once, after it has stayed in view for markDelay
    // (one press per step at most; the button is released the next step).
    m_input.buttons &= static_cast<std::uint8_t>(~kMarkLesion);
    for (int k = 0; k < 32; ++k) {
        const auto bit = std::uint32_t{1} << k;
        auto& since = m_inViewSince[static_cast<size_t>(k)];
        if ((frame.lesionsInView & bit) == 0) {
            since = -1.0;
            continue;
        }
        if (since < 0.0) {
            since = loop.time();
        }
        if ((m_marked & bit) == 0 && loop.time() - since >= m_style.markDelay &&
            (m_input.buttons & kMarkLesion) == 0) {
            m_input.buttons |= kMarkLesion;
            m_marked |= bit;
        }
    }

    // A loop is reduced once the tip stops following the shaft (the
    // clinical warning sign); while the tip still advances the expert goes
    // on and reduces the loop from further in, where the tip holds.
    const bool looped =
        loop.loops().current() != LoopKind::None && loop.loops().signals().tipAdvanceRatio > kTipLags;
    const bool reduce = m_style.reducesLoops && looped && !m_reductions.passing(frame.tipArcLength);
    const bool backOff = force > forceLimit || reduce;
    bool still = false;
    if (!m_style.aimsBeforeInserting || (m_phase != Phase::Insert && m_phase != Phase::SlideBy)) {
        m_stillSince = -1.0;
    } else if (m_stillSince < 0.0 || m_input.insertion > m_stillAt + kBlockedFeed) {
        m_stillSince = loop.time();
        m_stillAt = m_input.insertion;
    } else if (loop.time() - m_stillSince >= kStillFor) {
        still = true;
        m_stillSince = -1.0;
    }
    switch (m_phase) {
    case Phase::Insert: {
        // Blocked: a dial at its stop and the scope hardly fed since (the
        // lumen keeps slipping off centre).
        const bool atStop = std::abs(m_input.dialUpDown) >= kUpDownStop - kNearStop ||
                            std::abs(m_input.dialLeftRight) >= kDialStop - kNearStop;
        if (!m_style.aimsBeforeInserting || !atStop) {
            m_blockedSince = -1.0;
        } else if (m_blockedSince < 0.0 || m_input.insertion > m_blockedAt + kBlockedFeed) {
            m_blockedSince = loop.time();
            m_blockedAt = m_input.insertion;
        }
        if (backOff) {
            if (reduce && force <= forceLimit && !m_reductions.reduceAt(frame.tipArcLength)) {
                break;  // a loop that came back here: let it be and push on through it
            }
            backOffBy(Phase::ReduceLoop, kReduceLength);
        } else if (loop.cecumReached() || m_input.insertion >= maxInsertion) {
            m_phase = Phase::Withdraw;
        } else if ((m_blockedSince >= 0.0 && loop.time() - m_blockedSince >= kBlockedFor) || still) {
            // Pull back and re-approach; after kPullBacksPerBend of those at
            // the same bend, slide by it.
            if (m_bendArc < 0.0 || frame.tipArcLength > m_bendArc + kNewBend) {
                m_pullBacks = 0;
                m_bendArc = frame.tipArcLength;
            }
            m_blockedSince = -1.0;
            if (m_pullBacks < kPullBacksPerBend) {
                ++m_pullBacks;
                backOffBy(Phase::PullBack, kPullBackLength);
            } else {
                m_phase = Phase::SlideBy;
                m_slideUntil = std::min(m_input.insertion + kSlideLength, maxInsertion);
            }
        } else if (!m_style.aimsBeforeInserting || m_offCentre < kAimedWithin) {
            m_input.insertion = std::min(m_input.insertion + m_style.insertSpeed * dt, maxInsertion);
        }
        break;
    }
    case Phase::PullBack:
        // Let the dials go and withdraw: the sigmoid straightens and the tip
        // unhooks; it is aimed again on the way in.
        if (!letDialsGo(kUnhookRate * dt)) {
            break;  // unhook the tip before pulling
        }
        if (holdPull(force, forceLimit, loop.time())) {
            break;
        }
        m_input.insertion = std::max(m_input.insertion - 0.5 * m_style.insertSpeed * dt, 0.0);
        if (m_input.insertion <= m_reduceUntil) {
            m_phase = Phase::Insert;
        }
        break;
    case Phase::SlideBy:
        // Advance slowly with a light touch, the tip deflected towards the
        // lumen, until the lumen comes back to the centre of the view.
        if (backOff) {
            backOffBy(Phase::ReduceLoop, kReduceLength);
        } else if (m_offCentre < kAimedWithin) {
            m_phase = Phase::Insert;
        } else if (m_input.insertion >= m_slideUntil || still) {
            m_pullBacks = 0;  // start the round again: pull back, re-aim, slide
            backOffBy(Phase::PullBack, kPullBackLength);
        } else if (force < kSlideForce) {
            m_input.insertion = std::min(m_input.insertion + kSlideSpeed * dt, maxInsertion);
        }
        break;
    case Phase::ReduceLoop:
        // Ease the dials back while backing off, and unhook the tip before pulling.
        if (m_style.aimsBeforeInserting && !letDialsGo(2.0 * dt)) {
            break;
        }
        // Withdraw with clockwise torque (clockwise seen from the operator:
        // negative rotation), counter-clockwise from a reverse alpha; while
        // the pull is held, the turn goes on alone.
        if (m_style.reducesLoops) {
            m_input.rotation += reductionTurn(loop.loops().current()) * m_style.reductionTurnRate * dt;
        }
        if (holdPull(force, forceLimit, loop.time())) {
            break;
        }
        m_input.insertion = std::max(m_input.insertion - 0.5 * m_style.insertSpeed * dt, 0.0);
        if (m_input.insertion <= m_reduceUntil &&
            (loop.loops().current() == LoopKind::None || m_input.insertion <= m_reduceFloor)) {
            m_phase = Phase::Insert;
        }
        break;
    case Phase::Withdraw:
        m_input.insertion = std::max(m_input.insertion - m_style.withdrawSpeed * dt, 0.0);
        m_input.rotation -= 0.3 * std::sin(0.5 * loop.time()) * dt;  // sweep the view, clockwise first
        m_finished = m_input.insertion <= kWithdrawnTo;
        break;
    }
    return m_input;
}

void ScriptedOperator::backOffBy(Phase phase, double length)
{
    m_phase = phase;
    m_reduceUntil = std::max(0.0, m_input.insertion - length);
    m_reduceFloor = std::max(0.0, m_input.insertion - kReduceAtMost);
}

bool ScriptedOperator::holdPull(double force, double limit, double now)
{
    if (!m_style.limitsPull || -force <= limit) {
        m_pullHeldSince = -1.0;
        return false;
    }
    if (m_pullHeldSince < 0.0) {
        m_pullHeldSince = now;
    } else if (now - m_pullHeldSince >= kPullHeldFor) {
        m_pullHeldSince = -1.0;
        m_phase = Phase::Insert;  // give the back-off up: the colon holds the shaft
    }
    return true;
}

bool ScriptedOperator::letDialsGo(double fraction)
{
    m_input.dialUpDown *= 1.0 - fraction;
    m_input.dialLeftRight *= 1.0 - fraction;
    return std::max(std::abs(m_input.dialUpDown), std::abs(m_input.dialLeftRight)) <= kUnhooked;
}

InputSample ReplayOperator::next(const ProcedureLoop& /*loop*/)
{
    return m_next < m_trace.samples.size() ? m_trace.samples[m_next++] : m_trace.samples.back();
}

std::unique_ptr<Operator> makeOperator(std::string_view name)
{
    if (name == "expert") {
        return std::make_unique<ScriptedOperator>(expertStyle());
    }
    if (name == "novice") {
        return std::make_unique<ScriptedOperator>(noviceStyle());
    }
    if (name.rfind("replay:", 0) == 0) {
        InputTrace trace = readTrace(std::string(name.substr(7)));
        if (trace.samples.empty()) {
            throw params::ParameterError("operator = " + std::string(name) + ": the trace holds no samples");
        }
        return std::make_unique<ReplayOperator>(std::move(trace));
    }
    throw params::ParameterError("operator = \"" + std::string(name) +
                                 "\" is not one of expert, novice, replay:TRACE");
}

}  // namespace colonosim::procedure
