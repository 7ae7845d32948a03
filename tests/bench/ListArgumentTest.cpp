// The report commands' numeric arguments: a value in range is taken, and
// anything else is refused naming the flag, the value and the range.

#include "bench/ListArgument.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace {

using colonosim::bench::parseList;
using colonosim::bench::parseNumber;

std::string refusal(const std::string& text, double low, double high)
{
    try {
        (void)parseNumber("--seconds", text, low, high);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "";
}

TEST(ListArgument, ANumberInItsRangeIsTaken)
{
    EXPECT_EQ(parseNumber("--seconds", "35", 1.0, 600.0), 35.0);
    EXPECT_EQ(parseNumber("--seconds", "1", 1.0, 600.0), 1.0);
    EXPECT_EQ(parseNumber("--window", "2.5e0", 0.5, 60.0), 2.5);
}

TEST(ListArgument, AnythingElseIsRefusedNamingFlagValueAndRange)
{
    EXPECT_EQ(refusal("x", 1.0, 600.0), "--seconds: value 'x' is not a number in [1, 600]");
    EXPECT_EQ(refusal("3abc", 1.0, 600.0), "--seconds: value '3abc' is not a number in [1, 600]");
    EXPECT_EQ(refusal("", 1.0, 600.0), "--seconds: value '' is not a number in [1, 600]");
    EXPECT_EQ(refusal("601", 1.0, 600.0), "--seconds: value '601' is not a number in [1, 600]");
    EXPECT_EQ(refusal("nan", 1.0, 600.0), "--seconds: value 'nan' is not a number in [1, 600]");
}

TEST(ListArgument, AListTakesEachValueAndRefusesTheFirstBadOne)
{
    EXPECT_EQ(parseList("--seeds", "1,2.5,3", 0.0, 10.0), (std::vector<double>{1.0, 2.5, 3.0}));
    EXPECT_THROW((void)parseList("--seeds", "1,,3", 0.0, 10.0), std::invalid_argument);
    EXPECT_THROW((void)parseList("--seeds", "1,11", 0.0, 10.0), std::invalid_argument);
    EXPECT_THROW((void)parseList("--seeds", "", 0.0, 10.0), std::invalid_argument);
}

}  // namespace
