#include "case_generator/RateCheck.h"

#include "case_generator/DeterministicMath.h"
#include "case_generator/EnvironmentSampler.h"
#include "case_generator/Quantity.h"
#include "simcore/geometry/AnatomyParameters.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace colonosim::cases {

double RateEntry::z() const
{
    if (trials == 0) {
        return 0.0;
    }
    const double se = mean ? sd / std::sqrt(static_cast<double>(trials))
                           : std::sqrt(expected * (1.0 - expected) / static_cast<double>(trials));
    return se > 0.0 ? (realised - expected) / se : (realised == expected ? 0.0 : INFINITY);
}

namespace {

/// Weights of (sex, age) in the generated population under the sex and age constraints.
struct PopulationMix {
    std::vector<std::tuple<Sex, int, double>> cells;

    PopulationMix(const Statistics& stats, const Constraints& constraints)
    {
        const int lo = std::max(stats.minAge(), constraints.ageMin.value_or(0));
        const int hi = std::min(stats.maxAge(), constraints.ageMax.value_or(1000));
        double total = 0.0;
        for (const Sex sex : {Sex::Female, Sex::Male}) {
            const double sexWeight =
                constraints.sex ? (*constraints.sex == sex ? 1.0 : 0.0)
                                : (sex == Sex::Female ? stats.sexFemale.value : 1.0 - stats.sexFemale.value);
            for (std::size_t b = 0; b < stats.ageBands.size(); ++b) {
                const IntRange& band = stats.ageBands[b];
                for (int age = std::max(band.lo, lo); age <= std::min(band.hi, hi); ++age) {
                    const double w = sexWeight * stats.ageShare[b] / (band.hi - band.lo + 1);
                    if (w > 0.0) {
                        cells.emplace_back(sex, age, w);
                        total += w;
                    }
                }
            }
        }
        for (auto& cell : cells) {
            std::get<2>(cell) /= total;
        }
    }

    /// E[f(sex, age)] over the cells of `only` (or all when nullopt); nullopt when none.
    [[nodiscard]] std::optional<double> average(const std::function<double(Sex, int)>& f,
                                                std::optional<Sex> only = std::nullopt) const
    {
        double sum = 0.0;
        double weight = 0.0;
        for (const auto& [sex, age, w] : cells) {
            if (!only || *only == sex) {
                sum += w * f(sex, age);
                weight += w;
            }
        }
        return weight > 0.0 ? std::optional<double>(sum / weight) : std::nullopt;
    }
};

struct Counter {
    double sum = 0;
    double sumSquares = 0;
    std::uint64_t n = 0;
    void add(double x)
    {
        sum += x;
        sumSquares += x * x;
        ++n;
    }
    void add(bool hit) { add(hit ? 1.0 : 0.0); }
};

/// Per-adenoma probability of being advanced (size >= 10 mm or advanced histology).
double advancedShare(const Statistics& s)
{
    return s.sizeClassShare[0] * s.advancedHistology[0] + s.sizeClassShare[1] * s.advancedHistology[1] +
           s.sizeClassShare[2];
}

/// E[x^n] for n zero-truncated Poisson(lambda).
double truncatedPoissonPgf(double lambda, double x)
{
    return (detmath::exp(lambda * x) - 1.0) / (detmath::exp(lambda) - 1.0);
}

/// Mean of normal(mean, sd) truncated to [lo, hi], by the midpoint rule.
double truncatedNormalMean(const NormalLaw& law, double lo, double hi)
{
    constexpr int steps = 20000;
    const double a = std::max(lo, law.mean - 10.0 * law.sd);
    const double b = std::min(hi, law.mean + 10.0 * law.sd);
    double weight = 0.0;
    double moment = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double x = a + (b - a) * (i + 0.5) / steps;
        const double z = (x - law.mean) / law.sd;
        const double w = detmath::exp(-0.5 * z * z);
        weight += w;
        moment += w * x;
    }
    return moment / weight;
}

}  // namespace

std::vector<RateEntry> checkRates(const CaseGenerator& generator, std::uint64_t n, std::uint64_t seed,
                                  const Constraints& constraints)
{
    const Statistics& s = generator.statistics();
    std::map<std::string, Counter> count;
    for (std::uint64_t i = 0; i < n; ++i) {
        const Case c = generator.generate(seed + i, constraints);
        const Sex sex = c.patient.sex;
        const std::string suffix = sex == Sex::Male ? "_men" : "_women";
        int adenomas = 0;
        int advanced = 0;
        int proximal = 0;
        bool cancer = false;
        bool anySerrated = false;
        bool ssl = false;
        bool lipoma = false;
        for (const Lesion& l : c.lesions) {
            if (isAdenoma(l.histology)) {
                ++adenomas;
                advanced += isAdvancedAdenoma(l) ? 1 : 0;
                proximal += isProximal(l.place.segment) ? 1 : 0;
                const double mm = l.size * 1000.0;
                count["adenoma_size_le5mm"].add(mm <= 5.5);
                count["adenoma_size_6to9mm"].add(mm > 5.5 && mm <= 9.5);
                count["adenoma_size_ge10mm"].add(mm > 9.5);
                count["adenoma_morphology_sessile"].add(l.paris == Paris::Is || l.paris == Paris::Isp);
                count["adenoma_morphology_pedunculated"].add(l.paris == Paris::Ip);
                count["adenoma_morphology_flat"].add(isFlatOrDepressed(l.paris) && l.paris != Paris::IIc);
                count["adenoma_morphology_depressed"].add(l.paris == Paris::IIc);
                count["adenoma_histology_villous_component"].add(l.histology == Histology::Tubulovillous ||
                                                                 l.histology == Histology::Villous);
            }
            cancer = cancer || l.histology == Histology::Adenocarcinoma;
            anySerrated = anySerrated || isSerrated(l.histology);
            ssl = ssl || l.histology == Histology::SessileSerrated;
            lipoma = lipoma || l.histology == Histology::Lipoma;
        }
        count["sex_female"].add(sex == Sex::Female);
        count["any_adenoma"].add(adenomas > 0);
        count["any_adenoma" + suffix].add(adenomas > 0);
        count["advanced_adenoma"].add(advanced > 0);
        count["colorectal_cancer" + suffix].add(cancer);
        count["any_serrated_lesion" + suffix].add(anySerrated);
        count["sessile_serrated_lesion" + suffix].add(ssl);
        count["lipoma"].add(lipoma);
        count["ulcerative_colitis"].add(c.colitis != ColitisExtent::None);
        count["hemorrhoids"].add(c.hemorrhoidGrade > 0);
        count["diverticulosis"].add(!c.diverticula.empty());
        count["diverticulosis_more_than_10"].add(c.diverticula.size() > 10);
        for (const Diverticulum& d : c.diverticula) {
            count["diverticula_in_sigmoid"].add(d.place.segment == Segment::Sigmoid);
        }
        count["prior_abdominal_surgery"].add(c.history.priorAbdominalSurgery);
        if (sex == Sex::Female) {
            count["hysterectomy_women"].add(c.history.hysterectomy);
        }
        count["bmi_obese" + suffix].add(c.patient.bmi >= s.obeseThreshold);
        count["bmi_severe_obese" + suffix].add(c.patient.bmi >= s.severeThreshold);
        count["ascending_colon_mobile"].add(c.anatomy.ascendingMobileFraction > 0.0);
        count["descending_colon_mobile"].add(c.anatomy.descendingMobile);
        count["colon_length_cm" + suffix].add(c.anatomy.colonLength() * 100.0);
        const auto& p = c.environment.preparation;
        const int prepClass = preparationClass(p[0].boston, p[1].boston, p[2].boston);
        count["boston_all_segments_ge2"].add(prepClass == 0);
        count["boston_total_3_to_5"].add(prepClass == 1);
        count["boston_total_0_to_2"].add(prepClass == 2);
        if (adenomas > 0) {
            count["adenomas_per_positive_patient"].add(static_cast<double>(adenomas));
            count["adenoma_location_only_proximal"].add(proximal == adenomas);
            count["adenoma_location_only_distal"].add(proximal == 0);
            count["adenoma_location_both"].add(proximal > 0 && proximal < adenomas);
        }
    }

    const PopulationMix mix(s, constraints);
    std::vector<RateEntry> out;
    const auto add = [&](const std::string& name, const std::string& source, std::optional<double> expected,
                         bool mean = false) {
        const auto it = count.find(name);
        if (!expected || it == count.end() || it->second.n == 0) {
            return;
        }
        const Counter& k = it->second;
        RateEntry e{name, source, *expected, k.sum / static_cast<double>(k.n), k.n, mean, 0.0};
        if (mean && k.n > 1) {
            const double m = e.realised;
            e.sd = std::sqrt(std::max(0.0, (k.sumSquares - k.n * m * m) / static_cast<double>(k.n - 1)));
        }
        out.push_back(e);
    };
    const auto bySex = [&](const std::function<double(Sex, int)>& f, Sex sex) { return mix.average(f, sex); };
    const auto all = [&](const std::function<double(Sex, int)>& f) { return mix.average(f); };

    if (!constraints.sex) {
        add("sex_female", s.sexFemale.source, s.sexFemale.value);
    }
    const auto adenoma = [&](Sex x, int a) { return s.adenomaRate(x, a); };
    add("any_adenoma", s.adenomaPrevalenceSource, all(adenoma));
    add("any_adenoma_men", s.adenomaPrevalenceSource, bySex(adenoma, Sex::Male));
    add("any_adenoma_women", s.adenomaPrevalenceSource, bySex(adenoma, Sex::Female));
    const double q = advancedShare(s);
    const double noAdvanced = truncatedPoissonPgf(s.adenomaCountLambda, 1.0 - q);
    add("advanced_adenoma",
        "derived from the adenoma prevalence, the count law and the advanced share per adenoma (Tsai & Strum "
        "2011: "
        "size >= 10 mm or advanced histology); published: 6.3% (Ferlitsch 2011), 4.6% (Wong 2019)",
        all([&](Sex x, int a) { return s.adenomaRate(x, a) * (1.0 - noAdvanced); }));
    const auto cancerRate = [&](Sex x, int a) { return s.cancerRate(x, a); };
    add("colorectal_cancer_men", s.cancerSource, bySex(cancerRate, Sex::Male));
    add("colorectal_cancer_women", s.cancerSource, bySex(cancerRate, Sex::Female));
    add("any_serrated_lesion_men", s.serratedSource,
        bySex([&](Sex x, int) { return s.anySerrated.of(x); }, Sex::Male));
    add("any_serrated_lesion_women", s.serratedSource,
        bySex([&](Sex x, int) { return s.anySerrated.of(x); }, Sex::Female));
    add("sessile_serrated_lesion_men", s.serratedSource,
        bySex([&](Sex x, int) { return s.sessileSerrated.of(x); }, Sex::Male));
    add("sessile_serrated_lesion_women", s.serratedSource,
        bySex([&](Sex x, int) { return s.sessileSerrated.of(x); }, Sex::Female));
    add("adenomas_per_positive_patient", s.adenomaCountSource, s.adenomaCountMean, true);
    add("adenoma_location_only_proximal", s.locationSource, s.onlyProximal);
    add("adenoma_location_only_distal", s.locationSource, s.onlyDistal);
    add("adenoma_location_both", s.locationSource, s.bothRegions);
    add("adenoma_size_le5mm", s.sizeSource, s.sizeClassShare[0]);
    add("adenoma_size_6to9mm", s.sizeSource, s.sizeClassShare[1]);
    add("adenoma_size_ge10mm", s.sizeSource, s.sizeClassShare[2]);
    add("adenoma_morphology_sessile", s.morphologySource, s.morphologyShare[0]);
    add("adenoma_morphology_pedunculated", s.morphologySource, s.morphologyShare[1]);
    add("adenoma_morphology_flat", s.morphologySource, s.morphologyShare[2]);
    add("adenoma_morphology_depressed", s.morphologySource, s.morphologyShare[3]);
    double villous = 0.0;
    for (int c = 0; c < 3; ++c) {
        villous += s.sizeClassShare[c] * s.advancedHistology[c];
    }
    add("adenoma_histology_villous_component", s.histologySource,
        villous * (s.advancedHistologyShare[0] + s.advancedHistologyShare[1]));
    add("lipoma", s.lipoma.source, s.lipoma.value);
    add("ulcerative_colitis", s.colitis.source, s.colitis.value);
    add("hemorrhoids", s.hemorrhoids.source, s.hemorrhoids.value);
    add("diverticulosis", s.diverticulosisSource, all([&](Sex, int a) { return s.diverticulosisRate(a); }));
    add("diverticulosis_more_than_10", s.diverticulosisSource,
        all([&](Sex, int a) { return s.diverticulosisManyRate(a); }));
    add("diverticula_in_sigmoid", s.diverticulosisSource, s.diverticulumRegionShare[0]);
    add("prior_abdominal_surgery", s.priorSurgery.source, s.priorSurgery.value);
    add("hysterectomy_women", s.hysterectomySource,
        bySex([&](Sex, int a) { return s.hysterectomyRate(a); }, Sex::Female));
    if (!constraints.bmiMin && !constraints.bmiMax) {
        // The log-normal laws pass through the published shares by construction.
        add("bmi_obese_men", s.bmiSource, s.bmiObese.male);
        add("bmi_obese_women", s.bmiSource, s.bmiObese.female);
        add("bmi_severe_obese_men", s.bmiSource, s.bmiSevere.male);
        add("bmi_severe_obese_women", s.bmiSource, s.bmiSevere.female);
    }
    add("ascending_colon_mobile", s.mobilitySource, all([&](Sex x, int) { return s.ascendingMobile.of(x); }));
    add("descending_colon_mobile", s.descendingMobile.source, s.descendingMobile.value);
    // The law is truncated to the lengths the declared segment ranges can hold.
    double minTotal = 0.0;
    double maxTotal = 0.0;
    for (const auto& field : geometry::AnatomyParameters::fields().first(geometry::kNumSegments)) {
        minTotal += field.spec->minValue;
        maxTotal += field.spec->maxValue;
    }
    const std::string lengthSource = s.colonLengthSource + "; truncated to the " +
                                     formatFixed(minTotal * 100, 0) + "-" + formatFixed(maxTotal * 100, 0) +
                                     " cm the declared segment ranges allow";
    add("colon_length_cm_men", lengthSource,
        truncatedNormalMean(s.colonLengthMale, minTotal, maxTotal) * 100.0, true);
    add("colon_length_cm_women", lengthSource,
        truncatedNormalMean(s.colonLengthFemale, minTotal, maxTotal) * 100.0, true);
    add("boston_all_segments_ge2", s.preparationSource, s.preparationClassShare[0]);
    add("boston_total_3_to_5", s.preparationSource, s.preparationClassShare[1]);
    add("boston_total_0_to_2", s.preparationSource, s.preparationClassShare[2]);
    return out;
}

}  // namespace colonosim::cases
