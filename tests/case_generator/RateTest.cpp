// Realised rates against the rates of the statistics file, for large n with
// fixed seeds. Bound: |z| <= 4.5 for every entry, z = (realised - expected) /
// SE with the binomial SE sqrt(p (1 - p) / n) for proportions and s / sqrt(n)
// for means (two-sided p = 7e-6 per entry, about 3e-4 over the ~45 entries).

#include "case_generator/RateCheck.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colonosim::cases {

namespace {
constexpr double kBound = 4.5;

void expectWithinBound(const std::vector<RateEntry>& entries)
{
    for (const RateEntry& e : entries) {
        EXPECT_LE(std::abs(e.z()), kBound) << e.name << ": expected " << e.expected << ", realised "
                                           << e.realised << " over " << e.trials << " (z = " << e.z() << ")";
    }
}

const RateEntry* find(const std::vector<RateEntry>& entries, const std::string& name)
{
    for (const RateEntry& e : entries) {
        if (e.name == name) {
            return &e;
        }
    }
    return nullptr;
}
}  // namespace

TEST(Rates, RealisedRatesMatchTheSourcesForTheWholePopulation)
{
    const std::vector<RateEntry> entries = checkRates(CaseGenerator(), 100000, 1, {});
    EXPECT_GE(entries.size(), 40u);
    const RateEntry* adenoma = find(entries, "any_adenoma");
    ASSERT_NE(adenoma, nullptr);
    EXPECT_EQ(adenoma->trials, 100000u);
    EXPECT_NE(adenoma->source.find("Corley"), std::string::npos);
    expectWithinBound(entries);
}

TEST(Rates, SexAndAgeConstraintsKeepTheConditionalRates)
{
    Constraints constraints;
    constraints.sex = Sex::Female;
    constraints.ageMin = 50;
    constraints.ageMax = 54;
    const std::vector<RateEntry> entries = checkRates(CaseGenerator(), 40000, 777, constraints);
    const RateEntry* adenoma = find(entries, "any_adenoma_women");
    ASSERT_NE(adenoma, nullptr);
    EXPECT_DOUBLE_EQ(adenoma->expected, 0.15);  // Corley 2013, women 50-54
    EXPECT_EQ(find(entries, "any_adenoma_men"), nullptr);
    const RateEntry* diverticulosis = find(entries, "diverticulosis");
    ASSERT_NE(diverticulosis, nullptr);
    // Peery 2016: 35% at <= 50 and 40% at 51-60, one year in five at <= 50.
    EXPECT_NEAR(diverticulosis->expected, 0.2 * 0.35 + 0.8 * 0.40, 1e-12);
    expectWithinBound(entries);
}

TEST(Rates, AWrongExpectedRateIsDetected)
{
    // The bound is tight enough to see a 2-point error in the adenoma rate.
    const std::vector<RateEntry> entries = checkRates(CaseGenerator(), 100000, 1, {});
    RateEntry shifted = *find(entries, "any_adenoma");
    shifted.expected += 0.02;
    EXPECT_GT(std::abs(shifted.z()), kBound);
}

}  // namespace colonosim::cases
