// Plain input devices: the rate integration shared by keyboard and gamepad,
// the gamepad's standard mapping, and the error when no controller is there.
#include "simcore/devices/Gamepad.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

using namespace colonosim::devices;
using colonosim::procedure::InputSample;
using colonosim::procedure::validateInput;

TEST(ManualInput, FullDeflectionMovesAtTheDeclaredRates)
{
    const ManualRates rates;
    ManualInput input(rates);
    ManualControls c;
    c.insert = 1.0;
    c.twist = -1.0;
    c.upDown = 1.0;
    for (int i = 0; i < 1000; ++i) {
        input.update(c, 1e-3);
    }
    EXPECT_NEAR(input.input().insertion, rates.insertion, 1e-9);
    EXPECT_NEAR(input.input().rotation, -rates.rotation, 1e-9);
    EXPECT_NEAR(input.input().dialUpDown, rates.dial, 1e-9);
    EXPECT_EQ(input.input().dialLeftRight, 0.0);
}

TEST(ManualInput, TheDeadZoneHoldsAndTheRangesAreNeverLeft)
{
    ManualInput input;
    ManualControls drift;
    drift.insert = 0.05;
    drift.leftRight = -0.07;
    for (int i = 0; i < 1000; ++i) {
        input.update(drift, 1e-3);
    }
    EXPECT_EQ(input.input().insertion, 0.0);
    EXPECT_EQ(input.input().dialLeftRight, 0.0);
    ManualControls pull;
    pull.insert = -1.0;                                     // pulling out beyond the anus stays at zero
    pull.upDown = 1.0;                                      // the dial stops at its range
    pull.twist = std::numeric_limits<double>::quiet_NaN();  // a broken axis moves nothing
    pull.buttons = 0xFF;                                    // unknown bits are dropped
    for (int i = 0; i < 5000; ++i) {
        input.update(pull, 1e-3);
    }
    EXPECT_EQ(input.input().insertion, 0.0);
    EXPECT_EQ(input.input().dialUpDown, InputSample::dialSpec.maxValue);
    EXPECT_EQ(input.input().rotation, 0.0);
    EXPECT_EQ(validateInput(input.input()), "");
}

TEST(Gamepad, TheStandardMappingPushesWithTheStickAway)
{
    GamepadState s;
    s.leftY = -1.0;  // SDL: up is negative
    s.rightX = 1.0;
    s.a = true;
    s.y = true;
    const ManualControls c = controlsFrom(s);
    EXPECT_EQ(c.insert, 1.0);
    EXPECT_EQ(c.leftRight, -1.0);  // right stick right turns the tip right
    EXPECT_EQ(c.buttons, colonosim::procedure::kAir | colonosim::procedure::kMarkLesion);
}

TEST(Gamepad, AMissingControllerIsAClearError)
{
    // CI machines have no controller: opening index 99 fails whatever is plugged in.
    try {
        Gamepad pad(99);
        FAIL() << "opened a controller at index 99";
    } catch (const DeviceError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("gamepad"), std::string::npos) << what;
    }
}

}  // namespace
