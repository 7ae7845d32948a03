#include "simcore/params/Parameter.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>

namespace colonosim::params {
namespace {

struct Spring {
    static constexpr ParameterSpec stiffnessSpec{"stiffness",       "N/m", 100.0, 1.0, 1000.0,
                                                 "spring constant", "test"};
    double stiffness = stiffnessSpec.defaultValue;
};
constexpr std::array<Field<Spring>, 1> kSpringFields{{{&Spring::stiffnessSpec, &Spring::stiffness}}};

TEST(Parameter, DefaultComesFromTheDeclaration)
{
    EXPECT_DOUBLE_EQ(Spring{}.stiffness, 100.0);
}

TEST(Parameter, RejectionNamesFieldValueAndRange)
{
    Spring spring;
    try {
        setField<Spring>("spring", kSpringFields, spring, "stiffness", 5000.0);
        FAIL() << "out-of-range value accepted";
    } catch (const ParameterError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("spring.stiffness"), std::string::npos) << message;
        EXPECT_NE(message.find("5000"), std::string::npos) << message;
        EXPECT_NE(message.find("[1, 1000] N/m"), std::string::npos) << message;
    }
    EXPECT_DOUBLE_EQ(spring.stiffness, 100.0) << "a refused value must not be stored";
}

TEST(Parameter, NonFiniteValuesAreRefused)
{
    Spring spring;
    spring.stiffness = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(validateFields<Spring>("spring", kSpringFields, spring), ParameterError);
    spring.stiffness = std::numeric_limits<double>::infinity();
    EXPECT_THROW(validateFields<Spring>("spring", kSpringFields, spring), ParameterError);
}

TEST(Parameter, UnknownNameIsRefused)
{
    Spring spring;
    EXPECT_THROW(setField<Spring>("spring", kSpringFields, spring, "stifness", 10.0), ParameterError);
}

TEST(Parameter, MarkdownTableListsEveryField)
{
    const auto specs = specsOf<Spring>(kSpringFields);
    const std::string table = markdownTable("spring", specs);
    EXPECT_NE(table.find("| `spring.stiffness` | N/m | 100 | 1 – 1000 |"), std::string::npos) << table;
}

}  // namespace
}  // namespace colonosim::params
