#pragma once
/// \file
/// The population statistics the generator draws from, read from the
/// versioned data file data/population-statistics.json (compiled into the
/// library; another file can be given instead). Each group keeps its source
/// text, which the rates self-check prints next to each rate. Lengths are SI
/// here (m); the data file writes cm and mm as its keys say.

#include "case_generator/Case.h"

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace colonosim::cases {

/// A data file that cannot be used: the message names the file and the key.
class StatisticsError : public std::runtime_error {
public:
    explicit StatisticsError(const std::string& message) : std::runtime_error(message) {}
};

struct Sourced {
    double value = 0;
    std::string source;
};

struct BySex {
    double male = 0;
    double female = 0;
    [[nodiscard]] double of(Sex sex) const { return sex == Sex::Male ? male : female; }
};

struct NormalLaw {
    double mean = 0;
    double sd = 0;
};

/// A log-normal law: exp(mu + sigma z).
struct LogNormalLaw {
    double mu = 0;
    double sigma = 0;
};

struct IntRange {
    int lo = 0;
    int hi = 0;
};

struct Range {
    double lo = 0;
    double hi = 0;
};

struct WeightedSegments {
    std::vector<Segment> segments;
    std::vector<double> share;
};

struct DifficultyRule {
    std::string name;
    double points = 0;
    std::string source;
};

struct Statistics {
    std::string version;

    // Population.
    Sourced sexFemale;
    std::vector<IntRange> ageBands;
    std::vector<double> ageShare;
    std::string ageSource;

    std::vector<std::string> femaleNames, maleNames, familyNames;

    // Body.
    NormalLaw heightMale, heightFemale;  ///< m
    Range height;                        ///< m
    BySex bmiObese, bmiSevere, bmiMean;  ///< shares and the published means
    LogNormalLaw bmiMale, bmiFemale;     ///< fitted through the two shares
    double obeseThreshold = 30, severeThreshold = 40;
    Range bmi;
    std::string bmiSource;

    std::vector<double> indicationShare;  ///< by Indication
    std::string indicationSource;

    // History.
    Sourced priorSurgery;
    std::array<double, 2> hysterectomyAges{}, hysterectomyShare{};
    std::string hysterectomySource;
    std::vector<IntRange> anticoagulantBands;
    std::vector<double> anticoagulantShare;
    std::vector<double> anticoagulantTypeShare;  ///< antiplatelet, VKA, DOAC
    IntRange hysterectomyAdhesionCount, otherAdhesionCount;
    WeightedSegments hysterectomyAdhesionSegments, otherAdhesionSegments;
    double otherSurgeryAdhesionChance = 0;
    Range adhesionStiffness;  ///< N/m

    // Anatomy (m).
    NormalLaw colonLengthMale, colonLengthFemale;
    std::string colonLengthSource;
    std::array<double, geometry::kNumSegments> segmentBaseMale{}, segmentBaseFemale{};
    std::array<double, geometry::kNumSegments> segmentLogSd{};
    double redundantSigmoid = 0, redundantTransverse = 0;
    std::array<double, geometry::kNumSegments> diameterMedian{};
    double diameterLogSd = 0;
    BySex ascendingMobile;
    Range ascendingMobileFraction;
    Sourced descendingMobile;
    std::string mobilitySource;
    LogNormalLaw transverseMesentery, sigmoidMesentery, mobileMesentery;

    // Tuning (SI).
    double wallModulus = 0, wallModulusPerYear = 0, wallThickness = 0;
    double mesenteryModulus = 0, mesenteryThicknessPerBmi = 0, mesenteryHeightPerBmiBelow22 = 0;
    double surroundingDamping = 0, surroundingDampingPerBmiOver25 = 0;
    double diverticularWallModulus = 1, diverticularWallThickness = 1, diverticularSigmoidDiameter = 1;
    double colitisWallModulus = 1, colitisWallThickness = 1, colitisDiameter = 1;
    double adhesionTissueStiffness = 0;

    // Adenoma.
    std::array<std::vector<double>, 2> adenomaPrevalence;  ///< [Sex][age band]
    std::string adenomaPrevalenceSource;
    double adenomaCountMean = 0;
    double adenomaCountLambda = 0;  ///< zero-truncated Poisson parameter with that mean
    std::string adenomaCountSource;
    double onlyProximal = 0, onlyDistal = 0, bothRegions = 0;
    std::string locationSource;
    std::array<double, 3> sizeClassShare{}, advancedHistology{};
    std::array<std::vector<int>, 2> smallSizes;  ///< mm values of the <= 5 and 6-9 classes
    std::array<std::vector<double>, 2> smallSizeShare;
    std::vector<IntRange> largeSizeRanges;  ///< mm
    std::vector<double> largeSizeShare;
    std::string sizeSource;
    std::array<double, 3> advancedHistologyShare{};  ///< tubulovillous, villous, tubular high grade
    std::string histologySource;
    std::array<double, 4> morphologyShare{};  ///< sessile, pedunculated, flat, depressed
    std::array<double, 2> sessileParis{}, flatParis{}, lstParis{};
    std::string morphologySource;

    // Cancer.
    BySex cancerPrevalence;
    std::string cancerSource;
    double cancerProximal = 0;
    IntRange cancerSize;
    std::vector<Paris> cancerParis;
    std::vector<double> cancerParisShare;

    // Serrated.
    BySex anySerrated, sessileSerrated;
    double traditionalSerrated = 0;
    std::string serratedSource;
    double sessileSerratedProximal = 0, hyperplasticDistal = 0, traditionalDistal = 0;
    std::array<double, 3> sessileSerratedSize{}, hyperplasticSize{}, traditionalSize{};
    struct ParisMix {
        std::vector<Paris> paris;
        std::vector<double> share;
    };
    ParisMix sessileSerratedParis, hyperplasticParis, traditionalParis;

    // Diverticulosis.
    std::array<int, 3> diverticulosisAgeUpper{};
    std::array<double, 3> diverticulosisAny{}, diverticulosisMany{};
    std::array<double, 4>
        diverticulumRegionShare{};  ///< sigmoid, descending+splenic, transverse, ascending+hepatic
    Range diverticulumDiameter;     ///< m
    std::string diverticulosisSource;

    // Other findings.
    Sourced hemorrhoids;
    std::array<double, 4> hemorrhoidGradeShare{};
    double hemorrhoidRiskPerBmi = 1;
    Sourced lipoma;
    std::array<double, 6> lipomaLocationShare{};
    double lipomaPedunculated = 0;
    LogNormalLaw lipomaSize;  ///< mm
    IntRange lipomaSizeRange;
    Sourced colitis;
    std::array<double, 3> colitisExtentShare{};

    // Environment.
    std::array<double, 4> preparationClassShare{};
    std::array<Range, 4> residualStool{}, residualFluid{};  ///< by score; fraction, m^3
    std::string preparationSource;
    Range compliance;
    double referencePressure = 0;  ///< Pa

    // Lesion appearance.
    Range adenomaStiffness, serratedStiffness, carcinomaStiffness, lipomaStiffness;  ///< Pa
    std::array<double, 3> missRateBySize{};
    std::array<double, 4> missOddsRatio{};  ///< pedunculated, sessile, flat, depressed

    std::vector<DifficultyRule> difficulty;

    /// The file compiled into the library.
    [[nodiscard]] static const Statistics& builtIn();
    /// Parses a data file; `name` is used in error messages.
    [[nodiscard]] static Statistics fromJson(std::string_view text, const std::string& name);

    [[nodiscard]] int ageBandOf(int age) const;
    [[nodiscard]] int minAge() const { return ageBands.front().lo; }
    [[nodiscard]] int maxAge() const { return ageBands.back().hi; }
    [[nodiscard]] const LogNormalLaw& bmiLaw(Sex sex) const { return sex == Sex::Male ? bmiMale : bmiFemale; }
    [[nodiscard]] double adenomaRate(Sex sex, int age) const;
    /// Cancer prevalence at an age: the sex rate times the adenoma age gradient.
    [[nodiscard]] double cancerRate(Sex sex, int age) const;
    [[nodiscard]] double hysterectomyRate(int age) const;
    [[nodiscard]] double anticoagulantRate(int age) const;
    [[nodiscard]] double diverticulosisRate(int age) const;
    [[nodiscard]] double diverticulosisManyRate(int age) const;
    /// P(hyperplastic) so that any serrated lesion has its published rate.
    [[nodiscard]] double hyperplasticRate(Sex sex) const;
    /// E[relative risk(BMI)] over the sex's BMI law, to keep the hemorrhoid share.
    [[nodiscard]] double hemorrhoidNormaliser(Sex sex) const { return hemorrhoidNorm.of(sex); }
    [[nodiscard]] const DifficultyRule* difficultyRule(std::string_view name) const;

    // Derived when the file is read.
    BySex hemorrhoidNorm{1, 1};
    BySex adenomaMean;  ///< adenoma rate averaged over the age mix
};

/// The embedded data file's text (generated at configure time).
[[nodiscard]] std::string_view embeddedStatisticsJson();

}  // namespace colonosim::cases
