// A case's adhesions in the procedure loop (prior surgery binds the colon to
// the abdominal wall): places outside the colon are refused by name when the
// loop is built. The adhesions' effect and the hard case of an insertion
// against a fixed adhesion run whole procedures and are in
// ProcedureHardCasesTest.cpp (labelled slow).

#include "simcore/params/Parameter.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/procedure/WallSite.h"
#include "tests/procedure/LoopObservation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace colonosim;
using looptest::defaultColon;
using procedure::ProcedureLoop;
using procedure::ProcedureSettings;
using procedure::WallSite;

// A place the colon does not have, or a clock angle that is not a number, is
// refused when the loop is built, naming the adhesion, the value and the
// range; so is a list longer than the loop allows.
TEST(Adhesions, APlaceOutsideTheColonIsRefusedByName)
{
    const auto refusal = [](const ProcedureSettings& settings) -> std::string {
        try {
            ProcedureLoop loop(defaultColon(), settings);
        } catch (const params::ParameterError& e) {
            return e.what();
        }
        return "accepted";
    };
    ProcedureSettings beyond;
    beyond.adhesions = {WallSite{0.3, 0.0}, WallSite{9.0, 0.0}};
    const std::string message = refusal(beyond);
    EXPECT_NE(message.find("adhesions[1].arcLength = 9"), std::string::npos) << message;
    EXPECT_NE(message.find("allowed range [0, "), std::string::npos) << message;

    ProcedureSettings notAnAngle;
    notAnAngle.adhesions = {WallSite{0.3, std::nan("")}};
    EXPECT_NE(refusal(notAnAngle).find("adhesions[0].angle"), std::string::npos) << refusal(notAnAngle);

    ProcedureSettings tooMany;
    tooMany.adhesions.assign(ProcedureSettings::kMaxAdhesions + 1, WallSite{0.3, 0.0});
    EXPECT_NE(refusal(tooMany).find("adhesions: 33 adhesions is outside the allowed range [0, 32]"),
              std::string::npos)
        << refusal(tooMany);
}

}  // namespace
