// The renderer's coverage of a running session (% mucosa visualised): it
// grows as the scope goes in, depends on the simulated session only (a
// replay of the session's input trace covers the same wall, to the bit),
// and the loop's thread only hands the wall over.
#include "trainer_ui/cli/SessionCoverage.h"

#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

namespace {

using namespace colonosim;

struct Covered {
    double fraction = 0.0;
    int draws = 0;
    procedure::InputTrace trace;
};

Covered run(const geometry::ColonAnatomy& anatomy, procedure::Operator& driver, double seconds)
{
    procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    cli::SessionCoverage coverage(anatomy);
    double before = -1.0;
    const auto steps = static_cast<long>(seconds / loop.trace().loopStep);
    for (long s = 0; s < steps && !driver.finished(); ++s) {
        loop.step(driver.next(loop));
        coverage.observe(loop);
        if (s == steps / 2) {
            before = coverage.finalFraction();
        }
    }
    Covered out{coverage.finalFraction(), coverage.draws(), loop.trace()};
    EXPECT_GT(before, 0.0);
    EXPECT_GE(out.fraction, before) << "coverage never shrinks";
    return out;
}

TEST(SessionCoverage, GrowsAsTheScopeGoesInAndAReplayCoversTheSameWall)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    procedure::ScriptedOperator expert(procedure::expertStyle());
    const Covered first = run(anatomy, expert, 3.0);
    // Ten hand-overs a simulated second, every one drawn.
    EXPECT_EQ(first.draws, 30);
    EXPECT_GT(first.fraction, 0.01);
    EXPECT_LT(first.fraction, 0.5) << "3 s in the rectum sees part of the colon";
    procedure::ReplayOperator replay(first.trace);
    const Covered again = run(anatomy, replay, 3.0);
    EXPECT_EQ(again.draws, first.draws);
    EXPECT_EQ(again.fraction, first.fraction) << "bit for bit: simulated time drives it, not the wall clock";
}

}  // namespace
