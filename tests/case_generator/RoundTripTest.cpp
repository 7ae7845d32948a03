// XML round trip, and XSD validation of generated files with xmllint.

#include "case_generator/CaseGenerator.h"
#include "case_generator/CaseReader.h"
#include "case_generator/CaseWriter.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace colonosim::cases {

TEST(RoundTrip, ReadingAWrittenCaseGivesTheSameCase)
{
    const CaseGenerator generator;
    int lesions = 0;
    int diverticula = 0;
    int adhesions = 0;
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        const Case c = generator.generate(seed);
        const std::string text = writeCase(c);
        const ReadResult read = readCase(text, "case.xml");
        ASSERT_TRUE(read.ok()) << seed << ": " << (read.errors.empty() ? "" : read.errors.front());
        EXPECT_EQ(*read.value, c) << seed;
        EXPECT_EQ(writeCase(*read.value), text) << seed;
        lesions += static_cast<int>(c.lesions.size());
        diverticula += static_cast<int>(c.diverticula.size());
        adhesions += static_cast<int>(c.adhesions.size());
    }
    // The round trip covered every kind of list.
    EXPECT_GT(lesions, 100);
    EXPECT_GT(diverticula, 100);
    EXPECT_GT(adhesions, 20);
}

TEST(RoundTrip, GeneratedFilesValidateAgainstTheXsd)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("colonosim-xsd-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
         std::to_string(std::rand()));
    std::filesystem::create_directories(dir);
    const CaseGenerator generator;
    std::string files;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        const std::string path = (dir / ("case-" + std::to_string(seed) + ".xml")).string();
        Constraints constraints;
        if (seed % 4 == 0) {
            constraints.require = RequireExpression::parse("lesions>=3 and diverticula>=1");
        }
        writeCaseFile(generator.generate(seed, constraints), path);
        files += " " + path;
    }
    const std::string schema = std::string(COLONOSIM_SOURCE_DIR) + "/case_generator/schema/case.xsd";
    const std::string command = "xmllint --noout --schema " + schema + files + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;

    // The schema does refuse a broken file (a unit other than the fixed one).
    std::string text = writeCase(generator.generate(1));
    text.replace(text.find("unit=\"year\""), 11, "unit=\"days\"");
    const std::string broken = (dir / "broken.xml").string();
    std::ofstream(broken) << text;
    EXPECT_NE(std::system(("xmllint --noout --schema " + schema + " " + broken + " >/dev/null 2>&1").c_str()),
              0);
    std::filesystem::remove_all(dir);
}

}  // namespace colonosim::cases
