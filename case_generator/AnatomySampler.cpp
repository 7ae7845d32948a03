#include "case_generator/AnatomySampler.h"

#include "case_generator/DeterministicMath.h"
#include "case_generator/Quantity.h"
#include "simcore/geometry/AnatomyParameters.h"
#include "simcore/physics/TissueParameters.h"

#include <algorithm>

namespace colonosim::cases {

namespace {

using geometry::AnatomyParameters;
using geometry::kNumSegments;
using physics::TissueParameters;

constexpr int kRedrawBudget = 1000;

const params::ParameterSpec& lengthSpec(int i)
{
    return *AnatomyParameters::fields()[i].spec;
}

const params::ParameterSpec& diameterSpec(int i)
{
    return *AnatomyParameters::fields()[kNumSegments + i].spec;
}

double clampTo(double x, const params::ParameterSpec& spec)
{
    return std::clamp(x, spec.minValue, spec.maxValue);
}

/// A log-normal draw redrawn until it lies in the spec's range (value in SI).
double logNormalInRange(const LogNormalLaw& law, double scale, const params::ParameterSpec& spec,
                        Random& random)
{
    double x = 0.0;
    for (int i = 0; i < kRedrawBudget; ++i) {
        x = scale * detmath::exp(random.normal(law.mu, law.sigma));
        if (spec.accepts(x)) {
            return x;
        }
    }
    return clampTo(x, spec);
}

void sampleLengths(const Statistics& stats, Sex sex, Random& random, CaseAnatomy& anatomy)
{
    double minTotal = 0.0;
    double maxTotal = 0.0;
    for (int i = 0; i < kNumSegments; ++i) {
        minTotal += lengthSpec(i).minValue;
        maxTotal += lengthSpec(i).maxValue;
    }
    const NormalLaw& law = sex == Sex::Female ? stats.colonLengthFemale : stats.colonLengthMale;
    double total = random.normal(law.mean, law.sd);
    while (total < minTotal || total > maxTotal) {
        total = random.normal(law.mean, law.sd);
    }
    const auto& base = sex == Sex::Female ? stats.segmentBaseFemale : stats.segmentBaseMale;
    std::array<double, kNumSegments> weight{};
    for (int i = 0; i < kNumSegments; ++i) {
        weight[i] = base[i] * detmath::exp(stats.segmentLogSd[i] * random.normal(0.0, 1.0));
    }
    // Share the total in proportion to the weights; a segment that falls outside
    // its declared range is set to the bound it crossed and the rest is shared
    // again among the others, so the total keeps its law exactly.
    std::array<double, kNumSegments> length{};
    std::array<bool, kNumSegments> fixed{};
    for (int round = 0; round <= kNumSegments; ++round) {
        double remaining = total;
        double free = 0.0;
        for (int i = 0; i < kNumSegments; ++i) {
            if (fixed[i]) {
                remaining -= length[i];
            } else {
                free += weight[i];
            }
        }
        bool crossed = false;
        for (int i = 0; i < kNumSegments; ++i) {
            if (!fixed[i]) {
                length[i] = free > 0.0 ? weight[i] * remaining / free : 0.0;
            }
        }
        for (int i = 0; i < kNumSegments; ++i) {
            if (!fixed[i] && !lengthSpec(i).accepts(length[i])) {
                length[i] = clampTo(length[i], lengthSpec(i));
                fixed[i] = true;
                crossed = true;
            }
        }
        if (!crossed) {
            break;
        }
    }
    for (int i = 0; i < kNumSegments; ++i) {
        anatomy.length[i] = quantity::segmentLength.quantiseWithin(length[i], lengthSpec(i));
    }
}

}  // namespace

void sampleAnatomy(const Statistics& stats, const Patient& patient, Random& random, CaseAnatomy& anatomy)
{
    sampleLengths(stats, patient.sex, random, anatomy);
    for (int i = 0; i < kNumSegments; ++i) {
        const LogNormalLaw law{detmath::log(stats.diameterMedian[i]), stats.diameterLogSd};
        anatomy.diameter[i] = logNormalInRange(law, 1.0, diameterSpec(i), random);
    }
    anatomy.ascendingMobileFraction = 0.0;
    if (random.chance(stats.ascendingMobile.of(patient.sex))) {
        anatomy.ascendingMobileFraction = quantity::ascendingMobileFraction.quantise(
            random.uniform(stats.ascendingMobileFraction.lo, stats.ascendingMobileFraction.hi));
    }
    anatomy.descendingMobile = random.chance(stats.descendingMobile.value);
    anatomy.transverseMesenteryHeight = logNormalInRange(
        stats.transverseMesentery, 0.01, AnatomyParameters::transverseMesenteryHeightSpec, random);
    anatomy.sigmoidMesenteryHeight =
        logNormalInRange(stats.sigmoidMesentery, 0.01, AnatomyParameters::sigmoidMesenteryHeightSpec, random);
    anatomy.mobileColonMesenteryHeight = logNormalInRange(
        stats.mobileMesentery, 0.01, AnatomyParameters::mobileColonMesenteryHeightSpec, random);
}

bool colitisInvolves(ColitisExtent extent, Segment segment)
{
    switch (extent) {
    case ColitisExtent::None: return false;
    case ColitisExtent::Proctitis: return segment == Segment::Rectum;
    case ColitisExtent::LeftSided:
        return segment == Segment::Rectum || segment == Segment::Sigmoid || segment == Segment::Descending ||
               segment == Segment::SplenicFlexure;
    case ColitisExtent::Extensive: return true;
    }
    return false;
}

void tuneToPatient(const Statistics& stats, Case& c)
{
    const double bmi = c.patient.bmi;
    const bool severeDiverticulosis = c.diverticula.size() > 10;
    const bool colitis = c.colitis != ColitisExtent::None;
    double modulus = stats.wallModulus * (1.0 + stats.wallModulusPerYear * std::max(0, c.patient.age - 50));
    double thickness = stats.wallThickness;
    if (severeDiverticulosis) {
        modulus *= stats.diverticularWallModulus;
        thickness *= stats.diverticularWallThickness;
    }
    if (colitis) {
        modulus *= stats.colitisWallModulus;
        thickness *= stats.colitisWallThickness;
    }
    CaseTissue& t = c.tissue;
    t.wallYoungModulus =
        quantity::wallYoungModulus.quantiseWithin(modulus, TissueParameters::youngModulusSpec);
    t.wallThickness = quantity::wallThickness.quantiseWithin(thickness, TissueParameters::thicknessSpec);
    t.mesenteryModulus = quantity::mesenteryModulus.quantiseWithin(stats.mesenteryModulus,
                                                                   TissueParameters::mesenteryModulusSpec);
    t.mesenteryThickness = quantity::mesenteryThickness.quantiseWithin(
        stats.mesenteryThicknessPerBmi * bmi, TissueParameters::mesenteryThicknessSpec);
    t.adhesionStiffness = quantity::adhesionStiffness.quantiseWithin(stats.adhesionTissueStiffness,
                                                                     TissueParameters::adhesionSpec);
    t.surroundingDampingRate = quantity::surroundingDampingRate.quantiseWithin(
        stats.surroundingDamping * (1.0 + stats.surroundingDampingPerBmiOver25 * std::max(0.0, bmi - 25.0)),
        TissueParameters::surroundingDampingSpec);

    CaseAnatomy& a = c.anatomy;
    const double laxity = 1.0 + stats.mesenteryHeightPerBmiBelow22 * std::max(0.0, 22.0 - bmi);
    a.transverseMesenteryHeight = quantity::transverseMesenteryHeight.quantiseWithin(
        a.transverseMesenteryHeight * laxity, AnatomyParameters::transverseMesenteryHeightSpec);
    a.sigmoidMesenteryHeight = quantity::sigmoidMesenteryHeight.quantiseWithin(
        a.sigmoidMesenteryHeight * laxity, AnatomyParameters::sigmoidMesenteryHeightSpec);
    a.mobileColonMesenteryHeight = quantity::mobileColonMesenteryHeight.quantiseWithin(
        a.mobileColonMesenteryHeight * laxity, AnatomyParameters::mobileColonMesenteryHeightSpec);
    for (int i = 0; i < kNumSegments; ++i) {
        double d = a.diameter[i];
        if (severeDiverticulosis && static_cast<Segment>(i) == Segment::Sigmoid) {
            d *= stats.diverticularSigmoidDiameter;
        }
        if (colitisInvolves(c.colitis, static_cast<Segment>(i))) {
            d *= stats.colitisDiameter;
        }
        a.diameter[i] = quantity::segmentDiameter.quantiseWithin(d, diameterSpec(i));
    }
}

}  // namespace colonosim::cases
