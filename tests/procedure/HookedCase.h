#pragma once
/// \file
/// The inputs of the hooked hard case (issue 3;
/// HardCases.AHookedShaftPushedWithTorqueInARedundantSigmoidTwistedHardStaysStable,
/// and the report command build/bench/hooked_case): after the novice's
/// insertion into the redundant sigmoid, the tip is hooked with the up/down
/// dial at its stop and the shaft pushed on at 5 cm/s while it is turned
/// clockwise (seen from the operator) at 1 rad/s; then, with the insertion
/// held, the handle is twisted a whole turn counter-clockwise in 1 s and back
/// in 1 s.

#include "simcore/procedure/DeviceInput.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <cstddef>
#include <numbers>

namespace colonosim::looptest {

inline constexpr int kHookedNovice = 15000;  ///< steps of the novice's insertion
inline constexpr int kHookedCurl = 7000;     ///< steps of the hooked, turning push
inline constexpr int kHookedTwist = 2000;    ///< steps of the hard twist, each way
inline constexpr int kHookedSteps = kHookedNovice + kHookedCurl + 2 * kHookedTwist;

/// The input at step `s` (from kHookedNovice on), from the novice's last
/// input `held`; `dt` is the loop step, s.
inline procedure::InputSample hookedInput(const procedure::InputSample& held, int s, double dt)
{
    const int curl = std::min(s - kHookedNovice, kHookedCurl);
    procedure::InputSample input = held;
    input.dialUpDown = 3.0;  // beyond the clinical stop: clamped there
    input.insertion = held.insertion + 0.05 * curl * dt;
    input.rotation = held.rotation - 1.0 * curl * dt;  // clockwise seen from the operator
    const int twist = s - kHookedNovice - kHookedCurl;
    if (twist > 0) {
        const double turn = 2.0 * std::numbers::pi / kHookedTwist;  // rad per step
        input.rotation += turn * (twist <= kHookedTwist ? twist : 2 * kHookedTwist - twist);
    }
    return input;
}

/// The hooked case's inputs step by step: the novice's for kHookedNovice
/// steps, then hookedInput() from the novice's last input.
class HookedCaseDriver final : public procedure::Operator {
public:
    procedure::InputSample next(const procedure::ProcedureLoop& loop) override
    {
        if (m_step < kHookedNovice) {
            m_held = m_novice.next(loop);
            ++m_step;
            return m_held;
        }
        return hookedInput(m_held, m_step++, loop.trace().loopStep);
    }
    [[nodiscard]] bool finished() const override { return m_step >= kHookedSteps; }
    /// The phase of the last input: 0 the novice's insertion, 1 the hooked
    /// push, 2 the twist.
    [[nodiscard]] size_t phase() const
    {
        const int last = m_step - 1;
        return last < kHookedNovice ? 0 : (last < kHookedNovice + kHookedCurl ? 1 : 2);
    }
    /// The novice's last input, where the hooked push began.
    [[nodiscard]] const procedure::InputSample& held() const { return m_held; }

private:
    procedure::ScriptedOperator m_novice{procedure::noviceStyle()};
    procedure::InputSample m_held;
    int m_step = 0;
};

}  // namespace colonosim::looptest
