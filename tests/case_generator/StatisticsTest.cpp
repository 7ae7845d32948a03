// The statistics data file: it loads, every rate keeps its source, a rate is
// changed by editing the data, and a broken file names the key at fault.

#include "case_generator/Statistics.h"
#include "case_generator/CaseGenerator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace colonosim::cases {

namespace {
std::string editedJson(const std::string& from, const std::string& to)
{
    std::string text(embeddedStatisticsJson());
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) {
        text.replace(at, from.size(), to);
    }
    return text;
}

std::string errorOf(const std::string& text)
{
    try {
        (void)Statistics::fromJson(text, "edited.json");
    } catch (const StatisticsError& error) {
        return error.what();
    }
    return "";
}
}  // namespace

TEST(Statistics, BuiltInFileLoadsWithSourcesAndAssumptions)
{
    const Statistics& s = Statistics::builtIn();
    EXPECT_FALSE(s.version.empty());
    EXPECT_EQ(s.ageBands.size(), s.ageShare.size());
    EXPECT_NE(s.adenomaPrevalenceSource.find("Corley"), std::string::npos);
    EXPECT_NE(s.sexFemale.source.find("assumption"), std::string::npos);
    EXPECT_NE(s.adenomaCountSource.find("assumption"), std::string::npos);
    // The zero-truncated Poisson law has the published mean.
    EXPECT_NEAR(s.adenomaCountLambda / (1.0 - std::exp(-s.adenomaCountLambda)), 1.6, 1e-12);
    // Hyperplastic share is set so any serrated lesion keeps its rate.
    const double any = 1.0 - (1.0 - s.sessileSerrated.male) * (1.0 - s.traditionalSerrated) *
                                 (1.0 - s.hyperplasticRate(Sex::Male));
    EXPECT_NEAR(any, 0.22, 1e-12);
}

TEST(Statistics, ChangingARateIsADataEdit)
{
    const Statistics edited = Statistics::fromJson(
        editedJson("\"lipoma\": {\n    \"value\": 0.022", "\"lipoma\": {\n    \"value\": 1.0"),
        "edited.json");
    const CaseGenerator generator(edited);
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const Case c = generator.generate(seed);
        EXPECT_TRUE(std::any_of(c.lesions.begin(), c.lesions.end(), [](const Lesion& l) {
            return l.histology == Histology::Lipoma;
        })) << seed;
    }
}

TEST(Statistics, BrokenFilesNameTheKey)
{
    EXPECT_NE(errorOf("{ not json").find("not valid JSON"), std::string::npos);
    EXPECT_NE(
        errorOf(editedJson("\"share\": [0.50, 0.20, 0.20, 0.10]", "\"share\": [0.50, 0.20, 0.20, 0.20]"))
            .find("indication.share: adds up to"),
        std::string::npos);
    EXPECT_NE(
        errorOf(editedJson("\"sex_female\"", "\"sex_fem\"")).find("population.sex_female.value: missing"),
        std::string::npos);
    EXPECT_NE(errorOf(editedJson("\"name\": \"female\"", "\"name\": \"tall\"")).find("not a factor"),
              std::string::npos);
    EXPECT_NE(errorOf(editedJson("\"value\": 0.389", "\"value\": 1.389")).find("hemorrhoids.value"),
              std::string::npos);
}

}  // namespace colonosim::cases
