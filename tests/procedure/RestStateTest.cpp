// The colon's rest state the procedure starts from (ProcedureLoop's static
// solve under gravity and insufflation), on colons that converge slowly or
// overlap themselves at rest.
//   - data/colon-through-itself.xml, generated seed 7 kept as a file (the
//     test holds whatever the generator makes of seed 7 later): its
//     transverse colon runs 36 mm deep through the sigmoid's loop, so its
//     lumen's self-contact is active at rest, and its couplings are not the
//     springs'. The solve's assembled
//     preconditioner still factors at every iteration, and the solve stops
//     once it makes no headway. Before: the factorisation failed after the
//     first iteration (the self-contact probed into the wrong columns), the
//     diagonal fallback took 122,000 conjugate-gradient iterations and the
//     solve 47 iterations, 33 of them lowering 1.56 mN by 1e-8 N (32 s for
//     a 1 s procedure; 3.3 s after, with 17 iterations).
//   - The default colon and generated patient 3 (the slowest of seeds 1-8 to
//     converge, 29 iterations) still converge to the start's 1e-5 N.

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseReader.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/LumenSelfContact.h"
#include "simcore/physics/StaticSolver.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace colonosim;

constexpr double kStartTolerance = 1e-5;  // N: the procedure's start (ProcedureLoop.cpp)

void record(const physics::StaticResult& rest)
{
    testing::Test::RecordProperty("iterations", rest.iterations);
    testing::Test::RecordProperty("conjugate_gradient_iterations", rest.conjugateGradientIterations);
    testing::Test::RecordProperty("residual_uN", std::to_string(rest.residual * 1e6));
}

void expectConvergedEveryIterationFactored(const physics::StaticResult& rest)
{
    EXPECT_TRUE(rest.converged) << "residual " << rest.residual << " N after " << rest.iterations;
    EXPECT_FALSE(rest.stalled);
    EXPECT_LE(rest.residual, kStartTolerance);
    EXPECT_EQ(rest.factoredIterations, rest.iterations);
    // Measured: 14 iterations on the default colon, 29 on patient 3.
    EXPECT_LE(rest.iterations, 40);
}

TEST(RestState, TheDefaultColonConvergesWithItsTangentFactoredAtEveryIteration)
{
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(geometry::AnatomyParameters{});
    const procedure::ProcedureLoop loop(anatomy, procedure::ProcedureSettings{});
    record(loop.restSolve());
    expectConvergedEveryIterationFactored(loop.restSolve());
}

TEST(RestState, TheSlowestGeneratedColonStillConvergesToTheStartsTolerance)
{
    const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(3));
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    const procedure::ProcedureLoop loop(anatomy, cases::procedureSettings(scene));
    record(loop.restSolve());
    expectConvergedEveryIterationFactored(loop.restSolve());
}

TEST(RestState, AColonPressedIntoItselfAtRestIsSolvedWithTheFactorAndStopsWithoutHeadway)
{
    const cases::ReadResult file = cases::readCaseFile(std::string(COLONOSIM_SOURCE_DIR) +
                                                       "/tests/procedure/data/colon-through-itself.xml");
    ASSERT_TRUE(file.ok());
    const cases::SceneSpec scene = cases::toScene(*file.value);
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(scene.anatomy);
    const procedure::ProcedureLoop loop(anatomy, cases::procedureSettings(scene));
    const physics::StaticResult& rest = loop.restSolve();
    record(rest);
    ASSERT_NE(loop.colon().selfContact, nullptr);
    EXPECT_GT(loop.colon().selfContact->overlappingPairs(loop.colon().body.positions()), 0)
        << "the case this test is about: the self-contact holds at rest";
    EXPECT_EQ(rest.factoredIterations, rest.iterations) << "the factorisation failed";
    // With the factor each tangent solve takes a few iterations (measured:
    // 168 over 17); the diagonal fallback took about 2,600 each.
    EXPECT_LE(rest.conjugateGradientIterations, 20 * rest.iterations);
    // Measured: 1.56 mN left after 17 iterations, stalled.
    EXPECT_LE(rest.iterations, 25);
    EXPECT_TRUE(rest.converged || rest.stalled);
    EXPECT_LT(rest.residual, 2e-3);
}

}  // namespace
