// Byte-identical reproduction: the same seed and versions give the same XML,
// in this run and on any machine. The golden files were written by this
// generator; a change of output on another machine or compiler, or an
// unintended change of the generator, fails here. After an intended change,
// bump kGeneratorVersion (or the statistics version) and regenerate them:
//   colonosim case generate --seed 2024 --out tests/case_generator/golden/case-seed-2024.xml
//   colonosim case generate --seed 7 --sex F --require "flat_lesion(6-9mm, right)"
//       --out tests/case_generator/golden/case-seed-7-flat-lesion.xml  (one line)

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseWriter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace colonosim::cases {

namespace {
std::string golden(const std::string& name)
{
    std::ifstream in(std::string(COLONOSIM_SOURCE_DIR) + "/tests/case_generator/golden/" + name,
                     std::ios::binary);
    EXPECT_TRUE(in.good()) << name;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
}  // namespace

TEST(Reproduction, SameSeedGivesTheSameBytes)
{
    const CaseGenerator generator;
    for (std::uint64_t seed : {0ULL, 1ULL, 99ULL, 18446744073709551615ULL}) {
        EXPECT_EQ(writeCase(generator.generate(seed)), writeCase(generator.generate(seed))) << seed;
    }
    EXPECT_NE(writeCase(generator.generate(1)), writeCase(generator.generate(2)));
}

TEST(Reproduction, GoldenCaseIsReproducedByteForByte)
{
    EXPECT_EQ(writeCase(CaseGenerator().generate(2024)), golden("case-seed-2024.xml"));
}

TEST(Reproduction, GoldenConstrainedCaseIsReproducedByteForByte)
{
    Constraints constraints;
    constraints.sex = Sex::Female;
    constraints.require = RequireExpression::parse("flat_lesion(6-9mm, right)");
    EXPECT_EQ(writeCase(CaseGenerator().generate(7, constraints)), golden("case-seed-7-flat-lesion.xml"));
}

}  // namespace colonosim::cases
