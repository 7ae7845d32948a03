#include "simcore/geometry/AnatomyParameters.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace colonosim::geometry {
namespace {

TEST(AnatomyParameters, DefaultsAreValidAndTotalAbout166cm)
{
    const AnatomyParameters p;
    EXPECT_NO_THROW(p.validate());
    EXPECT_NEAR(p.totalLength(), 1.66, 1e-12);  // sum of the declared defaults
}

TEST(AnatomyParameters, RangesSpanThePopulation)
{
    // Utano 2021: 110-196 cm; Hanson 2007: 210.8 cm in incomplete examinations.
    double minTotal = 0.0;
    double maxTotal = 0.0;
    const std::set<std::string> lengths{"rectumLength",         "sigmoidLength",    "descendingLength",
                                        "splenicFlexureLength", "transverseLength", "hepaticFlexureLength",
                                        "ascendingLength",      "cecumLength"};
    std::set<std::string> names;
    for (const auto& field : AnatomyParameters::fields()) {
        names.insert(std::string(field.spec->name));
        EXPECT_FALSE(field.spec->source.empty()) << field.spec->name;
        EXPECT_TRUE(field.spec->accepts(field.spec->defaultValue)) << field.spec->name;
        if (lengths.contains(std::string(field.spec->name))) {
            minTotal += field.spec->minValue;
            maxTotal += field.spec->maxValue;
        }
    }
    EXPECT_EQ(names.size(), AnatomyParameters::fields().size()) << "a field is declared twice";
    EXPECT_EQ(names.size(), 30u);
    EXPECT_LE(minTotal, 1.10);
    EXPECT_GE(maxTotal, 2.10);
}

TEST(AnatomyParameters, DefaultMeshSizesMatchThePaper)
{
    const AnatomyParameters p;
    EXPECT_GE(p.visualNodesPerRing * p.visualRingCount, 50000.0);
    EXPECT_NEAR(p.physicsTargetNodeCount, 1872.0, 100.0);
}

TEST(AnatomyParameters, RejectionNamesFieldValueAndRange)
{
    AnatomyParameters p;
    p.sigmoidLength = 0.9;
    try {
        p.validate();
        FAIL() << "0.9 m sigmoid accepted";
    } catch (const params::ParameterError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("anatomy.sigmoidLength"), std::string::npos) << message;
        EXPECT_NE(message.find("0.9"), std::string::npos) << message;
        EXPECT_NE(message.find("[0.2, 0.7] m"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace colonosim::geometry
