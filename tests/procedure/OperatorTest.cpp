// The scripted expert at the sigmoid-descending junction of the default
// colon. Aiming with the left/right dial alone, it curled its tip there
// (the dial at its stop, the lumen still off centre) and never fed again:
// the tip stayed at or before 0.478 m along the colon for the whole 60 s.
// With torque steering and its ways past a bend it cannot aim through
// (pull back and re-approach, slide by), it gets further along: 0.668 m
// within 25 s when this was written (the descending colon starts at 0.55 m).

#include "simcore/procedure/Operator.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

using namespace colonosim;

TEST(ExpertOperator, GetsPastWhereAimingWithLeftRightAloneStalled)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    constexpr int kSteps = 25000;  // 25 s at 1 kHz
    double furthest = 0.0;         // m along the colon
    for (int s = 0; s < kSteps && !expert.finished(); ++s) {
        loop.step(expert.next(loop));
        furthest = std::max(furthest, loop.lastFrame().tipArcLength);
    }
    RecordProperty("furthest_m", std::to_string(furthest));
    EXPECT_GT(furthest, 0.52) << "the tip got past the junction where the expert used to stall (0.478 m)";
}

}  // namespace
