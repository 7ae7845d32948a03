// The heads-up display's words for the physics rate: said plainly while the
// loop keeps real time, with the share of real time when it falls behind.
#include "trainer_ui/app/HeadsUpDisplay.h"

#include <gtest/gtest.h>

namespace {

using colonosim::app::HeadsUpDisplay;

TEST(HeadsUpDisplay, SaysWhenThePhysicsIsBehindRealTime)
{
    EXPECT_EQ(HeadsUpDisplay::physicsWords(1001.0, 1000.0).toStdString(), "physics 1001 Hz");
    EXPECT_EQ(HeadsUpDisplay::physicsWords(960.0, 1000.0).toStdString(), "physics 960 Hz")
        << "within 5% of real time nothing is said";
    EXPECT_EQ(HeadsUpDisplay::physicsWords(612.0, 1000.0).toStdString(), "physics 612 Hz, 61% of real time");
    EXPECT_EQ(HeadsUpDisplay::physicsWords(2400.0, 4000.0, 4.0).toStdString(),
              "physics 2400 Hz, 60% of 4x real time");
    EXPECT_EQ(HeadsUpDisplay::physicsWords(0.0, 0.0).toStdString(), "physics 0 Hz")
        << "before the loop has a rate to ask for";
    // The first half second, or a haptic device that has not sent a frame:
    // no rate measured yet, and no alarm (the procedure screen's first
    // snapshot read "0% of real time" in amber before this).
    EXPECT_EQ(HeadsUpDisplay::physicsWords(0.0, 1000.0).toStdString(), "physics 0 Hz");
    EXPECT_FALSE(HeadsUpDisplay::behindRealTime(0.0, 1000.0));
    EXPECT_TRUE(HeadsUpDisplay::behindRealTime(612.0, 1000.0));
}

}  // namespace
