// The scripted expert on the default colon. Aiming with the left/right dial
// alone, it curled its tip at the sigmoid-descending junction (the dial at
// its stop, the lumen still off centre) and never fed again: the tip stayed
// at or before 0.478 m along the colon for the whole 60 s. With torque
// steering and its ways past a bend it cannot aim through (pull back and
// re-approach, slide by), it got to 0.668 m within 25 s, and then went to
// and fro in the descending colon, backing off at every loop the sigmoid
// stored. Now it reduces a loop only once the tip stops following the shaft
// (the clinical warning sign) and aims a lumen behind its tip by more bend,
// not a mirrored one: it passes the splenic flexure within a minute
// (the tip 1.02 m along the colon at 60 s when this was written, 0.735 m
// at 25 s; the transverse colon starts at 0.885 m).

#include "simcore/procedure/Operator.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace {

using namespace colonosim;

TEST(ExpertOperator, PassesTheSplenicFlexureWithinAMinute)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const geometry::Centreline& colon = loop.loops().colon();
    double transverseStart = colon.length();  // m along the colon
    for (double s = 0.0; s < colon.length(); s += 0.005) {
        if (geometry::sampleCentreline(colon, s).segment == geometry::Segment::Transverse) {
            transverseStart = s;
            break;
        }
    }
    ASSERT_LT(transverseStart, colon.length());
    double furthestAt25 = 0.0;  // m along the colon within 25 s
    double furthest = 0.0;      // within 60 s
    for (int s = 1; s <= 60000 && !expert.finished(); ++s) {
        loop.step(expert.next(loop));
        furthest = std::max(furthest, loop.lastFrame().tipArcLength);
        if (s == 25000) {
            furthestAt25 = furthest;
        }
    }
    RecordProperty("furthest_at_25s_m", std::to_string(furthestAt25));
    RecordProperty("furthest_m", std::to_string(furthest));
    RecordProperty("transverse_start_m", std::to_string(transverseStart));
    EXPECT_GT(furthestAt25, 0.52) << "the tip got past the junction where the expert used to stall (0.478 m)";
    EXPECT_GT(furthest, transverseStart + 0.05) << "the tip is in the transverse colon";
}

}  // namespace
