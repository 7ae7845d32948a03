// The expert's count of loop reductions at one place (Operator.h): two
// reductions begun within 5 cm of each other along the colon, and the loop
// that comes back there a third time is let be until the tip is 15 cm on;
// reductions at places further apart are all carried out.
#include "simcore/procedure/Operator.h"

#include <gtest/gtest.h>

namespace {

using colonosim::procedure::LoopReductionCount;

constexpr int kPerPlace = 2;
constexpr double kSamePlace = 0.05;   // m
constexpr double kPassLength = 0.15;  // m

TEST(LoopReductionCount, ALoopThatComesBackToThePlaceOfTwoReductionsIsLetBeFor15cm)
{
    LoopReductionCount count(kPerPlace, kSamePlace, kPassLength);
    EXPECT_FALSE(count.passing(0.40));
    EXPECT_TRUE(count.reduceAt(0.40));
    EXPECT_TRUE(count.reduceAt(0.42));   // 2 cm on: the same place, the second reduction
    EXPECT_FALSE(count.reduceAt(0.43));  // the third time there: let it be
    EXPECT_TRUE(count.passing(0.43));
    EXPECT_TRUE(count.passing(0.579));
    EXPECT_FALSE(count.passing(0.5801));  // 15 cm on from where it was let be
    // Past it the count starts afresh: the next loop is reduced.
    EXPECT_TRUE(count.reduceAt(0.60));
    EXPECT_TRUE(count.reduceAt(0.61));
    EXPECT_FALSE(count.reduceAt(0.62));
}

TEST(LoopReductionCount, ReductionsAtPlacesFurtherApartThan5cmAreAllCarriedOut)
{
    LoopReductionCount count(kPerPlace, kSamePlace, kPassLength);
    for (double arc = 0.30; arc < 1.0; arc += 0.06) {
        EXPECT_TRUE(count.reduceAt(arc)) << arc << " m";
        EXPECT_FALSE(count.passing(arc));
    }
}

TEST(LoopReductionCount, APlaceIsMeasuredFromItsFirstReduction)
{
    // Reductions that creep on 3 cm at a time: the third is 6 cm from the
    // first, a new place, and is carried out.
    LoopReductionCount count(kPerPlace, kSamePlace, kPassLength);
    EXPECT_TRUE(count.reduceAt(0.50));
    EXPECT_TRUE(count.reduceAt(0.53));
    EXPECT_TRUE(count.reduceAt(0.56));
    EXPECT_TRUE(count.reduceAt(0.57));
    EXPECT_FALSE(count.reduceAt(0.58));
}

}  // namespace
