#include "simcore/procedure/Operator.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace colonosim::procedure {

OperatorStyle expertStyle()
{
    return {0.03, 0.01, 8.0, true, 2.0, 0.5, true};
}

OperatorStyle noviceStyle()
{
    return {0.06, 0.04, 25.0, false, 0.5, 3.0};
}

InputSample ScriptedOperator::next(const ProcedureLoop& loop)
{
    const double dt = loop.trace().loopStep;
    const ProcedureFrame& frame = loop.lastFrame();
    const double force = loop.outputs().handleForce;
    const double maxInsertion = loop.scope().parameters().workingLength - 0.05;

    // The lumen as the camera sees it: the deformed lumen's centre 4 cm
    // ahead of the tip, in the tip's frame (x = the viewer's left, y = up,
    // z = forward; see TipPose).
    const geometry::Centreline& colon = loop.loops().colon();
    Eigen::Vector3d target = frame.tipPosition;
    if (!loop.lumen().contacts().empty()) {
        const contact::LumenStation& at = loop.lumen().contacts().back().station;
        target = loop.lumen().tube().centreAlong(at, m_phase == Phase::Withdraw ? -0.04 : 0.04);
    }
    const Eigen::Vector3d inCamera = loop.outputs().tip.rotation.transpose() * (target - frame.tipPosition);
    if (inCamera.norm() > 1e-6 && m_phase != Phase::Withdraw) {
        // Turn the dials towards the lumen, following its angular offset with
        // a first-order lag (the operator's reaction), within +-1 rad.
        double up = std::atan2(inCamera.y(), std::abs(inCamera.z()) + 1e-3);
        double left = std::atan2(inCamera.x(), std::abs(inCamera.z()) + 1e-3);
        const double follow = std::min(1.0, m_style.steeringGain * dt);
        if (m_style.aimsBeforeInserting) {
            if (m_phase != Phase::Insert) {
                up = 0.0;
                left = 0.0;
            }
            // Turn the dials while the lumen is off centre and hold them where it is centred.
            m_input.dialUpDown = std::clamp(m_input.dialUpDown + follow * up, -2.5, 2.5);
            m_input.dialLeftRight = std::clamp(m_input.dialLeftRight + follow * left, -2.5, 2.5);
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

    switch (m_phase) {
    case Phase::Insert: {
        const bool looped = loop.loops().current() != LoopKind::None;
        if (force > m_style.forceLimit || (m_style.reducesLoops && looped)) {
            m_phase = Phase::ReduceLoop;
            m_reduceUntil = std::max(0.0, m_input.insertion - 0.03);
        } else if (frame.tipArcLength >= colon.length() - 0.03 || m_input.insertion >= maxInsertion) {
            m_phase = Phase::Withdraw;
        } else if (!m_style.aimsBeforeInserting || m_offCentre < kAimedWithin) {
            m_input.insertion = std::min(m_input.insertion + m_style.insertSpeed * dt, maxInsertion);
        }
        break;
    }
    case Phase::ReduceLoop:
        if (m_style.aimsBeforeInserting) {
            m_input.dialUpDown *= 1.0 - 2.0 * dt;  // ease the dials back while backing off
            m_input.dialLeftRight *= 1.0 - 2.0 * dt;
        }
        // Withdraw with clockwise torque (clockwise seen from the operator: negative rotation).
        m_input.insertion = std::max(m_input.insertion - 0.5 * m_style.insertSpeed * dt, 0.0);
        if (m_style.reducesLoops) {
            m_input.rotation -= 0.5 * dt;
        }
        if (m_input.insertion <= m_reduceUntil) {
            m_phase = Phase::Insert;
        }
        break;
    case Phase::Withdraw:
        m_input.insertion = std::max(m_input.insertion - m_style.withdrawSpeed * dt, 0.0);
        m_input.rotation += 0.3 * std::sin(0.5 * loop.time()) * dt;  // sweep the view
        m_finished = m_input.insertion <= 0.05;
        break;
    }
    return m_input;
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
