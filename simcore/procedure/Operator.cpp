#include "simcore/procedure/Operator.h"

#include "simcore/geometry/CentrelineSampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace colonosim::procedure {

OperatorStyle expertStyle()
{
    return {0.03, 0.01, 8.0, true, 2.0};
}

OperatorStyle noviceStyle()
{
    return {0.06, 0.04, 25.0, false, 0.5};
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
        if (std::getenv("OPDBG") != nullptr && static_cast<long>(loop.time() * 1000.0) % 2000 == 0) {
            std::fprintf(stderr, "t=%.1f target in camera (%.1f %.1f %.1f) mm dials (%.2f %.2f)\n", loop.time(),
                         inCamera.x() * 1e3, inCamera.y() * 1e3, inCamera.z() * 1e3, m_input.dialUpDown,
                         m_input.dialLeftRight);
        }
        double up = std::atan2(inCamera.y(), std::abs(inCamera.z()) + 1e-3);
        double left = std::atan2(inCamera.x(), std::abs(inCamera.z()) + 1e-3);
        const double follow = std::min(1.0, m_style.steeringGain * dt);
        if (std::getenv("INTEGRAL") != nullptr) {
            if (m_phase != Phase::Insert) {
                up = 0.0;
                left = 0.0;
            }
            // Turn the dials while the lumen is off centre and hold them where it is centred.
            m_input.dialUpDown = std::clamp(m_input.dialUpDown + follow * up, -2.5, 2.5);
            static const double torque = std::getenv("TORQUE") ? std::atof(std::getenv("TORQUE")) : 0.0;
            // Torque steering: roll the view (shaft rotation) so the lumen comes into the up/down plane.
            m_input.rotation += torque * dt * std::clamp(left, -1.0, 1.0) * (up >= 0.0 ? 1.0 : -1.0);
            m_input.dialLeftRight =
                std::clamp(m_input.dialLeftRight + (torque > 0.0 ? 0.3 : 1.0) * follow * left, -2.5, 2.5);
            m_offCentre = std::hypot(up, left);
        } else {
        m_input.dialUpDown += follow * (std::clamp(up, -1.0, 1.0) - m_input.dialUpDown);
        m_input.dialLeftRight += follow * (std::clamp(left, -1.0, 1.0) - m_input.dialLeftRight);
        }
    } else {
        m_input.dialUpDown *= 1.0 - dt;  // relax the dials while withdrawing
        m_input.dialLeftRight *= 1.0 - dt;
    }

    switch (m_phase) {
    case Phase::Insert: {
        const bool looped = loop.loops().current() != LoopKind::None;
        if (force > m_style.forceLimit || (m_style.reducesLoops && looped)) {
            m_phase = Phase::ReduceLoop;
            m_reduceUntil = std::max(0.0, m_input.insertion - 0.03);
        } else if (frame.tipArcLength >= colon.length() - 0.03 || m_input.insertion >= maxInsertion) {
            m_phase = Phase::Withdraw;
        } else if (std::getenv("INTEGRAL") == nullptr || m_offCentre < 0.35) {
            m_input.insertion = std::min(m_input.insertion + m_style.insertSpeed * dt, maxInsertion);
            m_aimingSince = -1.0;
        } else if (std::getenv("SLIDE") != nullptr &&
                   std::max(std::abs(m_input.dialUpDown), std::abs(m_input.dialLeftRight)) >= 2.4) {
            // Slide by: the dials can turn no further, so feed slowly along the wall with them held.
            m_input.insertion =
                std::min(m_input.insertion + std::atof(std::getenv("SLIDE")) * m_style.insertSpeed * dt, maxInsertion);
        } else {
            // The lumen cannot be centred from here: back off and approach again.
            m_aimingSince = m_aimingSince < 0.0 ? loop.time() : m_aimingSince;
            if (std::getenv("BACKOFF") != nullptr && loop.time() - m_aimingSince > 1.5) {
                m_phase = Phase::ReduceLoop;
                m_reduceUntil = std::max(0.0, m_input.insertion - 0.03);
                m_aimingSince = -1.0;
            }
        }
        break;
    }
    case Phase::ReduceLoop:
        if (std::getenv("INTEGRAL") != nullptr) {
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
