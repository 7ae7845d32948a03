#include "case_generator/Statistics.h"

#include "case_generator/CaseNames.h"
#include "case_generator/DeterministicMath.h"
#include "case_generator/DifficultyEstimate.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace colonosim::cases {

namespace {

using nlohmann::json;

/// Walks the data file, naming the file and the key in every error.
class DataReader {
public:
    explicit DataReader(std::string name) : m_name(std::move(name)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& what) const
    {
        throw StatisticsError(m_name + ": " + path + ": " + what);
    }

    const json& at(const json& node, const std::string& path) const
    {
        const json* current = &node;
        std::size_t start = 0;
        while (start <= path.size()) {
            const std::size_t dot = path.find('.', start);
            const std::string key =
                path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
            if (current->is_array() && !key.empty() &&
                key.find_first_not_of("0123456789") == std::string::npos &&
                std::stoul(key) < current->size()) {
                current = &(*current)[std::stoul(key)];
            } else if (current->is_object() && current->contains(key)) {
                current = &(*current)[key];
            } else {
                fail(path, "missing");
            }
            if (dot == std::string::npos) {
                break;
            }
            start = dot + 1;
        }
        return *current;
    }

    double number(const json& node, const std::string& path, double lo = 0.0, double hi = 1e9) const
    {
        const json& value = at(node, path);
        if (!value.is_number()) {
            fail(path, "is not a number");
        }
        const double x = value.get<double>();
        if (!(x >= lo && x <= hi)) {
            fail(path, "= " + std::to_string(x) + " is outside [" + std::to_string(lo) + ", " +
                           std::to_string(hi) + "]");
        }
        return x;
    }

    double share(const json& node, const std::string& path) const { return number(node, path, 0.0, 1.0); }

    std::string text(const json& node, const std::string& path) const
    {
        const json& value = at(node, path);
        if (!value.is_string()) {
            fail(path, "is not a string");
        }
        return value.get<std::string>();
    }

    std::vector<double> numbers(const json& node, const std::string& path, std::size_t count, double lo,
                                double hi) const
    {
        const json& value = at(node, path);
        if (!value.is_array() || (count != 0 && value.size() != count)) {
            fail(path, "is not a list of " + std::to_string(count) + " numbers");
        }
        std::vector<double> out;
        for (const json& item : value) {
            if (!item.is_number() || !(item.get<double>() >= lo && item.get<double>() <= hi)) {
                fail(path, "holds a value that is not a number in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "]");
            }
            out.push_back(item.get<double>());
        }
        return out;
    }

    /// Shares that must add up to 1 (within 1e-9).
    std::vector<double> shares(const json& node, const std::string& path, std::size_t count) const
    {
        std::vector<double> out = numbers(node, path, count, 0.0, 1.0);
        double sum = 0.0;
        for (const double x : out) {
            sum += x;
        }
        if (std::abs(sum - 1.0) > 1e-9) {
            fail(path, "adds up to " + std::to_string(sum) + ", not 1");
        }
        return out;
    }

    template <std::size_t N>
    std::array<double, N> sharesArray(const json& node, const std::string& path) const
    {
        const std::vector<double> v = shares(node, path, N);
        std::array<double, N> out{};
        std::copy(v.begin(), v.end(), out.begin());
        return out;
    }

    template <std::size_t N>
    std::array<double, N> numbersArray(const json& node, const std::string& path, double lo, double hi) const
    {
        const std::vector<double> v = numbers(node, path, N, lo, hi);
        std::array<double, N> out{};
        std::copy(v.begin(), v.end(), out.begin());
        return out;
    }

    std::vector<std::string> strings(const json& node, const std::string& path) const
    {
        const json& value = at(node, path);
        if (!value.is_array() || value.empty()) {
            fail(path, "is not a non-empty list of names");
        }
        std::vector<std::string> out;
        for (const json& item : value) {
            if (!item.is_string() || item.get<std::string>().empty()) {
                fail(path, "holds an entry that is not a name");
            }
            out.push_back(item.get<std::string>());
        }
        return out;
    }

    Range range(const json& node, const std::string& path, double scale, double lo, double hi) const
    {
        const std::vector<double> v = numbers(node, path, 2, lo, hi);
        if (v[0] > v[1]) {
            fail(path, "has its lower bound above its upper bound");
        }
        return {v[0] * scale, v[1] * scale};
    }

    Range minMax(const json& node, const std::string& path, double scale, double lo, double hi) const
    {
        const double a = number(node, path + ".min", lo, hi);
        const double b = number(node, path + ".max", lo, hi);
        if (a > b) {
            fail(path, "min is above max");
        }
        return {a * scale, b * scale};
    }

    IntRange intRange(const json& node, const std::string& path, int lo, int hi) const
    {
        const Range r = range(node, path, 1.0, lo, hi);
        if (r.lo != std::floor(r.lo) || r.hi != std::floor(r.hi)) {
            fail(path, "is not a range of whole numbers");
        }
        return {static_cast<int>(r.lo), static_cast<int>(r.hi)};
    }

    Segment segment(const std::string& text, const std::string& path) const
    {
        const std::optional<Segment> s = parseName<Segment>(text);
        if (!s) {
            fail(path, "names an unknown segment \"" + text + "\" (one of: " + allowedNames<Segment>() + ")");
        }
        return *s;
    }

    WeightedSegments weightedSegments(const json& node, const std::string& path) const
    {
        WeightedSegments out;
        for (const std::string& name : strings(node, path + ".segments")) {
            out.segments.push_back(segment(name, path + ".segments"));
        }
        out.share = shares(node, path + ".segment_share", out.segments.size());
        return out;
    }

    Statistics::ParisMix parisMix(const json& node, const std::string& path) const
    {
        Statistics::ParisMix mix;
        for (const std::string& label : strings(node, path + ".labels")) {
            const std::optional<Paris> p = parseName<Paris>(label);
            if (!p) {
                fail(path + ".labels",
                     "unknown Paris class \"" + label + "\" (one of: " + allowedNames<Paris>() + ")");
            }
            mix.paris.push_back(*p);
        }
        mix.share = shares(node, path + ".share", mix.paris.size());
        return mix;
    }

    LogNormalLaw logNormalFromMoments(const json& node, const std::string& path) const
    {
        const double mean = number(node, path + ".mean", 1e-9, 1e9);
        const double sd = number(node, path + ".sd", 0.0, 1e9);
        const double s2 = detmath::log(1.0 + (sd / mean) * (sd / mean));
        return {detmath::log(mean) - 0.5 * s2, std::sqrt(s2)};
    }

private:
    std::string m_name;
};

/// lambda / (1 - e^-lambda) = mean, by bisection.
double zeroTruncatedPoissonLambda(double mean)
{
    double lo = 1e-9;
    double hi = 50.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        const double m = mid / (1.0 - detmath::exp(-mid));
        (m < mean ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

void readPopulation(const DataReader& r, const json& j, Statistics& s)
{
    s.version = r.text(j, "version");
    s.sexFemale = {r.share(j, "population.sex_female.value"), r.text(j, "population.sex_female.source")};
    const json& bands = r.at(j, "population.age_bands.years");
    if (!bands.is_array() || bands.empty()) {
        r.fail("population.age_bands.years", "is not a list of [first, last] ages");
    }
    for (std::size_t i = 0; i < bands.size(); ++i) {
        const IntRange band = r.intRange(bands, std::to_string(i), 0, 120);
        if (!s.ageBands.empty() && band.lo != s.ageBands.back().hi + 1) {
            r.fail("population.age_bands.years", "bands must follow each other without gaps");
        }
        s.ageBands.push_back(band);
    }
    s.ageShare = r.shares(j, "population.age_bands.share", s.ageBands.size());
    s.ageSource = r.text(j, "population.age_bands.source");
    s.femaleNames = r.strings(j, "names.female");
    s.maleNames = r.strings(j, "names.male");
    s.familyNames = r.strings(j, "names.family");
}

void readBody(const DataReader& r, const json& j, Statistics& s)
{
    s.heightMale = {r.number(j, "body.height_cm.male.mean", 100, 250) * 0.01,
                    r.number(j, "body.height_cm.male.sd", 0, 50) * 0.01};
    s.heightFemale = {r.number(j, "body.height_cm.female.mean", 100, 250) * 0.01,
                      r.number(j, "body.height_cm.female.sd", 0, 50) * 0.01};
    s.height = r.minMax(j, "body.height_cm", 0.01, 100, 250);
    s.obeseThreshold = r.number(j, "body.bmi.obese_threshold", 10, 100);
    s.severeThreshold = r.number(j, "body.bmi.severe_threshold", s.obeseThreshold + 1e-9, 100);
    s.bmi = r.minMax(j, "body.bmi", 1.0, 5, 150);
    s.bmiSource = r.text(j, "body.bmi.source");
    for (const Sex sex : {Sex::Male, Sex::Female}) {
        const std::string key = sex == Sex::Male ? "body.bmi.male" : "body.bmi.female";
        const double obese = r.number(j, key + ".obese_share", 1e-6, 1 - 1e-6);
        const double severe = r.number(j, key + ".severe_obese_share", 1e-6, obese - 1e-9);
        const double mean = r.number(j, key + ".mean", 5, 150);
        // Log-normal through P(BMI >= 30) and P(BMI >= 40) of the BMI as written,
        // to one decimal: a drawn 29.95 is written 30.0.
        const double obeseCut = s.obeseThreshold - 0.05;
        const double severeCut = s.severeThreshold - 0.05;
        const double z1 = detmath::normalQuantile(1.0 - obese);
        const double z2 = detmath::normalQuantile(1.0 - severe);
        const double sigma = (detmath::log(severeCut) - detmath::log(obeseCut)) / (z2 - z1);
        const LogNormalLaw law{detmath::log(obeseCut) - sigma * z1, sigma};
        (sex == Sex::Male ? s.bmiMale : s.bmiFemale) = law;
        (sex == Sex::Male ? s.bmiObese.male : s.bmiObese.female) = obese;
        (sex == Sex::Male ? s.bmiSevere.male : s.bmiSevere.female) = severe;
        (sex == Sex::Male ? s.bmiMean.male : s.bmiMean.female) = mean;
    }
    s.indicationShare = r.shares(j, "indication.share", EnumNames<Indication>::list.size());
    s.indicationSource = r.text(j, "indication.source");
}

void readHistory(const DataReader& r, const json& j, Statistics& s)
{
    s.priorSurgery = {r.share(j, "history.prior_abdominal_surgery.value"),
                      r.text(j, "history.prior_abdominal_surgery.source")};
    s.hysterectomyAges = r.numbersArray<2>(j, "history.hysterectomy_women.ages", 0, 120);
    s.hysterectomyShare = r.numbersArray<2>(j, "history.hysterectomy_women.share", 0, 1);
    if (!(s.hysterectomyAges[0] < s.hysterectomyAges[1])) {
        r.fail("history.hysterectomy_women.ages", "must rise");
    }
    s.hysterectomySource = r.text(j, "history.hysterectomy_women.source");
    const json& bands = r.at(j, "history.anticoagulant.age_bands");
    for (std::size_t i = 0; bands.is_array() && i < bands.size(); ++i) {
        s.anticoagulantBands.push_back(r.intRange(bands, std::to_string(i), 0, 120));
    }
    s.anticoagulantShare = r.numbers(j, "history.anticoagulant.share", s.anticoagulantBands.size(), 0.0, 1.0);
    s.anticoagulantTypeShare = r.shares(j, "history.anticoagulant.type_share", 3);
    const std::string adhesions = "history.adhesions";
    s.hysterectomyAdhesionCount = r.intRange(j, adhesions + ".after_hysterectomy.count", 0, 20);
    s.hysterectomyAdhesionSegments = r.weightedSegments(j, adhesions + ".after_hysterectomy");
    s.otherSurgeryAdhesionChance = r.share(j, adhesions + ".after_other_surgery.probability");
    s.otherAdhesionCount = r.intRange(j, adhesions + ".after_other_surgery.count", 0, 20);
    s.otherAdhesionSegments = r.weightedSegments(j, adhesions + ".after_other_surgery");
    s.adhesionStiffness = r.minMax(j, adhesions + ".stiffness_n_per_m", 1.0, 10.0, 10000.0);
}

void readAnatomy(const DataReader& r, const json& j, Statistics& s)
{
    s.colonLengthMale = {r.number(j, "anatomy.colon_length_cm.male.mean", 50, 300) * 0.01,
                         r.number(j, "anatomy.colon_length_cm.male.sd", 0, 100) * 0.01};
    s.colonLengthFemale = {r.number(j, "anatomy.colon_length_cm.female.mean", 50, 300) * 0.01,
                           r.number(j, "anatomy.colon_length_cm.female.sd", 0, 100) * 0.01};
    s.colonLengthSource = r.text(j, "anatomy.colon_length_cm.source");
    const std::vector<std::string> order = r.strings(j, "anatomy.segment_order");
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i >= EnumNames<Segment>::list.size() || order[i] != EnumNames<Segment>::list[i]) {
            r.fail("anatomy.segment_order",
                   "must list the segments anus to cecum: " + allowedNames<Segment>());
        }
    }
    constexpr std::size_t n = geometry::kNumSegments;
    s.segmentBaseMale = r.numbersArray<n>(j, "anatomy.segment_base_cm.male", 1, 200);
    s.segmentBaseFemale = r.numbersArray<n>(j, "anatomy.segment_base_cm.female", 1, 200);
    s.segmentLogSd = r.numbersArray<n>(j, "anatomy.segment_share_log_sd.value", 0, 1);
    s.redundantSigmoid = r.number(j, "anatomy.redundant_sigmoid_cm.value", 1, 200) * 0.01;
    s.redundantTransverse = r.number(j, "anatomy.redundant_transverse_cm.value", 1, 200) * 0.01;
    s.diameterMedian = r.numbersArray<n>(j, "anatomy.diameter_mm.median", 1, 200);
    for (double& d : s.diameterMedian) {
        d *= 0.001;
    }
    s.diameterLogSd = r.number(j, "anatomy.diameter_mm.log_sd", 0, 1);
    s.ascendingMobile = {r.share(j, "anatomy.ascending_mobile.male"),
                         r.share(j, "anatomy.ascending_mobile.female")};
    s.ascendingMobileFraction = r.range(j, "anatomy.ascending_mobile.mobile_fraction", 1.0, 0, 1);
    s.mobilitySource = r.text(j, "anatomy.ascending_mobile.source");
    s.descendingMobile = {r.share(j, "anatomy.descending_mobile.value"),
                          r.text(j, "anatomy.descending_mobile.source")};
    s.transverseMesentery = r.logNormalFromMoments(j, "anatomy.mesentery_height_cm.transverse");
    s.sigmoidMesentery = r.logNormalFromMoments(j, "anatomy.mesentery_height_cm.sigmoid");
    s.mobileMesentery = r.logNormalFromMoments(j, "anatomy.mesentery_height_cm.mobile_colon");
    const std::string t = "tuning.";
    s.wallModulus = r.number(j, t + "wall_modulus_mpa", 0.1, 100) * 1e6;
    s.wallModulusPerYear = r.number(j, t + "wall_modulus_per_year_over_50", 0, 0.1);
    s.wallThickness = r.number(j, t + "wall_thickness_mm", 0.1, 10) * 1e-3;
    s.mesenteryModulus = r.number(j, t + "mesentery_modulus_mpa", 0.01, 100) * 1e6;
    s.mesenteryThicknessPerBmi = r.number(j, t + "mesentery_thickness_mm_per_bmi", 0, 1) * 1e-3;
    s.mesenteryHeightPerBmiBelow22 = r.number(j, t + "mesentery_height_per_bmi_below_22", 0, 1);
    s.surroundingDamping = r.number(j, t + "surrounding_damping_per_s", 0, 1000);
    s.surroundingDampingPerBmiOver25 = r.number(j, t + "surrounding_damping_per_bmi_over_25", 0, 1);
    s.diverticularWallModulus = r.number(j, t + "severe_diverticulosis.wall_modulus", 0.1, 10);
    s.diverticularWallThickness = r.number(j, t + "severe_diverticulosis.wall_thickness", 0.1, 10);
    s.diverticularSigmoidDiameter = r.number(j, t + "severe_diverticulosis.sigmoid_diameter", 0.1, 10);
    s.colitisWallModulus = r.number(j, t + "colitis.wall_modulus", 0.1, 10);
    s.colitisWallThickness = r.number(j, t + "colitis.wall_thickness", 0.1, 10);
    s.colitisDiameter = r.number(j, t + "colitis.diameter", 0.1, 10);
    s.adhesionTissueStiffness = r.number(j, t + "adhesion_stiffness_n_per_m", 1, 1e5);
}

void readAdenoma(const DataReader& r, const json& j, Statistics& s)
{
    const std::size_t bands = s.ageBands.size();
    s.adenomaPrevalence[static_cast<int>(Sex::Male)] = r.numbers(j, "adenoma.prevalence.male", bands, 0, 1);
    s.adenomaPrevalence[static_cast<int>(Sex::Female)] =
        r.numbers(j, "adenoma.prevalence.female", bands, 0, 1);
    s.adenomaPrevalenceSource = r.text(j, "adenoma.prevalence.source");
    s.adenomaCountMean = r.number(j, "adenoma.count.mean", 1.000001, 20);
    s.adenomaCountLambda = zeroTruncatedPoissonLambda(s.adenomaCountMean);
    s.adenomaCountSource = r.text(j, "adenoma.count.source");
    s.onlyProximal = r.share(j, "adenoma.location.only_proximal");
    s.onlyDistal = r.share(j, "adenoma.location.only_distal");
    s.bothRegions = r.share(j, "adenoma.location.both");
    if (std::abs(s.onlyProximal + s.onlyDistal + s.bothRegions - 1.0) > 1e-9) {
        r.fail("adenoma.location", "only_proximal + only_distal + both must be 1");
    }
    const double lambda = s.adenomaCountLambda;
    const double single = lambda * detmath::exp(-lambda) / (1.0 - detmath::exp(-lambda));
    if (s.bothRegions > 1.0 - single) {
        r.fail("adenoma.location.both", "exceeds the share of patients with two or more adenomas");
    }
    s.locationSource = r.text(j, "adenoma.location.source");
    s.sizeClassShare = r.sharesArray<3>(j, "adenoma.size.share");
    s.advancedHistology = r.numbersArray<3>(j, "adenoma.size.advanced_histology", 0, 1);
    for (int c = 0; c < 2; ++c) {
        const std::string key = c == 0 ? "adenoma.size.mm_le5" : "adenoma.size.mm_6to9";
        for (const double v : r.numbers(j, key + ".values", 0, 1, c == 0 ? 5 : 9)) {
            s.smallSizes[c].push_back(static_cast<int>(v));
        }
        s.smallSizeShare[c] = r.shares(j, key + ".share", s.smallSizes[c].size());
    }
    const json& ranges = r.at(j, "adenoma.size.mm_ge10.ranges");
    for (std::size_t i = 0; ranges.is_array() && i < ranges.size(); ++i) {
        s.largeSizeRanges.push_back(r.intRange(ranges, std::to_string(i), 10, 100));
    }
    s.largeSizeShare = r.shares(j, "adenoma.size.mm_ge10.share", s.largeSizeRanges.size());
    s.sizeSource = r.text(j, "adenoma.size.source");
    s.advancedHistologyShare = r.sharesArray<3>(j, "adenoma.histology.advanced_share");
    s.histologySource = r.text(j, "adenoma.histology.source");
    s.morphologyShare = r.sharesArray<4>(j, "adenoma.morphology.share");
    s.sessileParis = r.sharesArray<2>(j, "adenoma.morphology.sessile_paris.share");
    s.flatParis = r.sharesArray<2>(j, "adenoma.morphology.flat_paris.share");
    s.lstParis = r.sharesArray<2>(j, "adenoma.morphology.flat_ge10_lst.share");
    s.morphologySource = r.text(j, "adenoma.morphology.source");
}

void readOtherPathology(const DataReader& r, const json& j, Statistics& s)
{
    s.cancerPrevalence = {r.share(j, "cancer.prevalence.male"), r.share(j, "cancer.prevalence.female")};
    s.cancerSource = r.text(j, "cancer.prevalence.source");
    s.cancerProximal = r.share(j, "cancer.proximal_share.value");
    s.cancerSize = {static_cast<int>(r.number(j, "cancer.size_mm.min", 1, 200)),
                    static_cast<int>(r.number(j, "cancer.size_mm.max", 1, 200))};
    const Statistics::ParisMix cancer = r.parisMix(j, "cancer.paris");
    s.cancerParis = cancer.paris;
    s.cancerParisShare = cancer.share;
    s.sessileSerratedParis = r.parisMix(j, "serrated.paris.sessile_serrated");
    s.hyperplasticParis = r.parisMix(j, "serrated.paris.hyperplastic");
    s.traditionalParis = r.parisMix(j, "serrated.paris.traditional_serrated");

    s.anySerrated = {r.share(j, "serrated.any.male"), r.share(j, "serrated.any.female")};
    s.serratedSource = r.text(j, "serrated.any.source");
    s.sessileSerrated = {r.share(j, "serrated.sessile_serrated.male"),
                         r.share(j, "serrated.sessile_serrated.female")};
    s.traditionalSerrated = r.share(j, "serrated.traditional_serrated.value");
    s.sessileSerratedProximal = r.share(j, "serrated.sessile_serrated_proximal.value");
    s.hyperplasticDistal = r.share(j, "serrated.hyperplastic_distal.value");
    s.traditionalDistal = r.share(j, "serrated.traditional_distal.value");
    s.sessileSerratedSize = r.sharesArray<3>(j, "serrated.size_share.sessile_serrated");
    s.hyperplasticSize = r.sharesArray<3>(j, "serrated.size_share.hyperplastic");
    s.traditionalSize = r.sharesArray<3>(j, "serrated.size_share.traditional_serrated");
    for (const Sex sex : {Sex::Male, Sex::Female}) {
        if (s.hyperplasticRate(sex) < 0.0) {
            r.fail("serrated.any", "is below the sessile and traditional serrated rates together");
        }
    }

    const std::vector<double> upper = r.numbers(j, "diverticulosis.age_upper", 3, 0, 1000);
    for (int i = 0; i < 3; ++i) {
        s.diverticulosisAgeUpper[i] = static_cast<int>(upper[i]);
    }
    s.diverticulosisAny = r.numbersArray<3>(j, "diverticulosis.any", 0, 1);
    s.diverticulosisMany = r.numbersArray<3>(j, "diverticulosis.more_than_10", 0, 1);
    for (int i = 0; i < 3; ++i) {
        if (s.diverticulosisMany[i] > s.diverticulosisAny[i]) {
            r.fail("diverticulosis.more_than_10", "exceeds the share with any diverticula");
        }
    }
    s.diverticulumRegionShare = r.sharesArray<4>(j, "diverticulosis.region_share");
    s.diverticulumDiameter = r.minMax(j, "diverticulosis.diameter_mm", 1e-3, 0.5, 30);
    s.diverticulosisSource = r.text(j, "diverticulosis.source");

    s.hemorrhoids = {r.share(j, "hemorrhoids.value"), r.text(j, "hemorrhoids.source")};
    s.hemorrhoidGradeShare = r.sharesArray<4>(j, "hemorrhoids.grade_share");
    s.hemorrhoidRiskPerBmi = r.number(j, "hemorrhoids.bmi_relative_risk_per_point", 0.5, 2);
    s.lipoma = {r.share(j, "lipoma.value"), r.text(j, "lipoma.source")};
    s.lipomaLocationShare = r.sharesArray<6>(j, "lipoma.location_share");
    s.lipomaPedunculated = r.share(j, "lipoma.pedunculated");
    s.lipomaSize = r.logNormalFromMoments(j, "lipoma.size_mm");
    s.lipomaSizeRange = {static_cast<int>(r.number(j, "lipoma.size_mm.min", 1, 200)),
                         static_cast<int>(r.number(j, "lipoma.size_mm.max", 1, 200))};
    s.colitis = {r.share(j, "colitis.ulcerative.value"), r.text(j, "colitis.ulcerative.source")};
    s.colitisExtentShare = r.sharesArray<3>(j, "colitis.extent.share");
}

void readEnvironment(const DataReader& r, const json& j, Statistics& s)
{
    s.preparationClassShare = r.sharesArray<4>(j, "preparation.share");
    for (int score = 0; score <= 3; ++score) {
        const std::string key = "score_" + std::to_string(score);
        s.residualStool[score] = r.range(j, "preparation.residual_stool_fraction." + key, 1.0, 0, 1);
        s.residualFluid[score] = r.range(j, "preparation.residual_fluid_ml." + key, 1e-6, 0, 5000);
    }
    s.preparationSource = r.text(j, "preparation.source");
    s.compliance = r.minMax(j, "insufflation.compliance", 1.0, 0.1, 10);
    s.referencePressure = r.number(j, "insufflation.reference_pressure_mmhg", 1, 80) * 133.322387415;
    const std::string a = "lesion_appearance.";
    s.adenomaStiffness = r.range(j, a + "stiffness_mpa.adenoma", 1e6, 0.01, 1000);
    s.serratedStiffness = r.range(j, a + "stiffness_mpa.serrated", 1e6, 0.01, 1000);
    s.carcinomaStiffness = r.range(j, a + "stiffness_mpa.carcinoma", 1e6, 0.01, 1000);
    s.lipomaStiffness = r.range(j, a + "stiffness_mpa.lipoma", 1e6, 0.01, 1000);
    s.missRateBySize = {r.share(j, a + "miss_rate_by_size.le5"), r.share(j, a + "miss_rate_by_size.6to9"),
                        r.share(j, a + "miss_rate_by_size.ge10")};
    s.missOddsRatio = {r.number(j, a + "miss_odds_ratio.pedunculated", 0.01, 100),
                       r.number(j, a + "miss_odds_ratio.sessile", 0.01, 100),
                       r.number(j, a + "miss_odds_ratio.flat", 0.01, 100),
                       r.number(j, a + "miss_odds_ratio.depressed", 0.01, 100)};
    const json& factors = r.at(j, "difficulty.factors");
    for (std::size_t i = 0; factors.is_array() && i < factors.size(); ++i) {
        const std::string key = "difficulty.factors." + std::to_string(i);
        s.difficulty.push_back(
            {r.text(j, key + ".name"), r.number(j, key + ".points", 0, 5), r.text(j, key + ".source")});
        const std::span<const std::string_view> known = knownDifficultyFactors();
        if (std::find(known.begin(), known.end(), s.difficulty.back().name) == known.end()) {
            r.fail(key + ".name",
                   "\"" + s.difficulty.back().name + "\" is not a factor the generator recognises");
        }
    }
}

/// Means of functions over the age mix and the BMI laws, for the derived rates.
void deriveNormalisers(Statistics& s)
{
    for (const Sex sex : {Sex::Male, Sex::Female}) {
        double mean = 0.0;
        for (std::size_t b = 0; b < s.ageBands.size(); ++b) {
            mean += s.ageShare[b] * s.adenomaPrevalence[static_cast<int>(sex)][b];
        }
        (sex == Sex::Male ? s.adenomaMean.male : s.adenomaMean.female) = mean;
        // E[rr^(BMI - 25)] by the midpoint rule on 4,000 quantiles of the BMI law.
        const LogNormalLaw& law = s.bmiLaw(sex);
        constexpr int quantiles = 4000;
        double sum = 0.0;
        const double lnRr = detmath::log(s.hemorrhoidRiskPerBmi);
        for (int i = 0; i < quantiles; ++i) {
            const double bmi =
                detmath::exp(law.mu + law.sigma * detmath::normalQuantile((i + 0.5) / quantiles));
            sum += detmath::exp(lnRr * (bmi - 25.0));
        }
        (sex == Sex::Male ? s.hemorrhoidNorm.male : s.hemorrhoidNorm.female) = sum / quantiles;
    }
}

}  // namespace

Statistics Statistics::fromJson(std::string_view text, const std::string& name)
{
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& error) {
        throw StatisticsError(name + ": not valid JSON: " + error.what());
    }
    const DataReader r(name);
    Statistics s;
    readPopulation(r, j, s);
    readBody(r, j, s);
    readHistory(r, j, s);
    readAnatomy(r, j, s);
    readAdenoma(r, j, s);
    readOtherPathology(r, j, s);
    readEnvironment(r, j, s);
    deriveNormalisers(s);
    return s;
}

const Statistics& Statistics::builtIn()
{
    static const Statistics statistics = fromJson(embeddedStatisticsJson(), "population-statistics.json");
    return statistics;
}

int Statistics::ageBandOf(int age) const
{
    for (std::size_t i = 0; i < ageBands.size(); ++i) {
        if (age >= ageBands[i].lo && age <= ageBands[i].hi) {
            return static_cast<int>(i);
        }
    }
    return age < minAge() ? 0 : static_cast<int>(ageBands.size()) - 1;
}

double Statistics::adenomaRate(Sex sex, int age) const
{
    return adenomaPrevalence[static_cast<int>(sex)][ageBandOf(age)];
}

double Statistics::cancerRate(Sex sex, int age) const
{
    return cancerPrevalence.of(sex) * adenomaRate(sex, age) / adenomaMean.of(sex);
}

double Statistics::hysterectomyRate(int age) const
{
    if (age <= hysterectomyAges[0]) {
        return hysterectomyShare[0];
    }
    if (age >= hysterectomyAges[1]) {
        return hysterectomyShare[1];
    }
    const double t = (age - hysterectomyAges[0]) / (hysterectomyAges[1] - hysterectomyAges[0]);
    return hysterectomyShare[0] + t * (hysterectomyShare[1] - hysterectomyShare[0]);
}

double Statistics::anticoagulantRate(int age) const
{
    for (std::size_t i = 0; i < anticoagulantBands.size(); ++i) {
        if (age >= anticoagulantBands[i].lo && age <= anticoagulantBands[i].hi) {
            return anticoagulantShare[i];
        }
    }
    return 0.0;
}

double Statistics::diverticulosisRate(int age) const
{
    for (int i = 0; i < 3; ++i) {
        if (age <= diverticulosisAgeUpper[i]) {
            return diverticulosisAny[i];
        }
    }
    return diverticulosisAny[2];
}

double Statistics::diverticulosisManyRate(int age) const
{
    for (int i = 0; i < 3; ++i) {
        if (age <= diverticulosisAgeUpper[i]) {
            return diverticulosisMany[i];
        }
    }
    return diverticulosisMany[2];
}

double Statistics::hyperplasticRate(Sex sex) const
{
    return 1.0 -
           (1.0 - anySerrated.of(sex)) / ((1.0 - sessileSerrated.of(sex)) * (1.0 - traditionalSerrated));
}

const DifficultyRule* Statistics::difficultyRule(std::string_view name) const
{
    for (const DifficultyRule& rule : difficulty) {
        if (rule.name == name) {
            return &rule;
        }
    }
    return nullptr;
}

}  // namespace colonosim::cases
