#include "case_generator/PatientSampler.h"

#include "case_generator/DeterministicMath.h"
#include "case_generator/Quantity.h"

#include <algorithm>

namespace colonosim::cases {

bool samplePatient(const Statistics& stats, const Constraints& constraints, Random& random, Patient& patient)
{
    patient.sex =
        constraints.sex ? *constraints.sex : (random.chance(stats.sexFemale.value) ? Sex::Female : Sex::Male);

    const int lo = std::max(stats.minAge(), constraints.ageMin.value_or(stats.minAge()));
    const int hi = std::min(stats.maxAge(), constraints.ageMax.value_or(stats.maxAge()));
    std::vector<double> weights(stats.ageBands.size(), 0.0);
    for (std::size_t b = 0; b < weights.size(); ++b) {
        const IntRange& band = stats.ageBands[b];
        const int years = std::min(band.hi, hi) - std::max(band.lo, lo) + 1;
        weights[b] = years > 0 ? stats.ageShare[b] * years / (band.hi - band.lo + 1) : 0.0;
    }
    const IntRange& band = stats.ageBands[random.choose(weights)];
    patient.age = random.integer(std::max(band.lo, lo), std::min(band.hi, hi));

    const std::vector<std::string>& given = patient.sex == Sex::Female ? stats.femaleNames : stats.maleNames;
    patient.givenName = given[random.below(given.size())];
    patient.familyName = stats.familyNames[random.below(stats.familyNames.size())];

    const NormalLaw& heightLaw = patient.sex == Sex::Female ? stats.heightFemale : stats.heightMale;
    double height = random.normal(heightLaw.mean, heightLaw.sd);
    while (height < stats.height.lo || height > stats.height.hi) {
        height = random.normal(heightLaw.mean, heightLaw.sd);
    }
    patient.height = quantity::height.quantise(height);

    const double bmiLo = std::max(stats.bmi.lo, constraints.bmiMin.value_or(stats.bmi.lo));
    const double bmiHi = std::min(stats.bmi.hi, constraints.bmiMax.value_or(stats.bmi.hi));
    const LogNormalLaw& law = stats.bmiLaw(patient.sex);
    for (int draw = 0;; ++draw) {
        if (draw == kBmiDrawBudget) {
            return false;
        }
        const double bmi = quantity::bmi.quantise(detmath::exp(random.normal(law.mu, law.sigma)));
        if (bmi >= bmiLo && bmi <= bmiHi) {
            patient.bmi = bmi;
            break;
        }
    }
    patient.weight = quantity::weight.quantise(patient.bmi * patient.height * patient.height);
    return true;
}

Indication sampleIndication(const Statistics& stats, Random& random)
{
    return static_cast<Indication>(random.choose(stats.indicationShare));
}

namespace {
void addAdhesions(const IntRange& count, const WeightedSegments& where, Random& random,
                  std::vector<Adhesion>& adhesions)
{
    const int n = random.integer(count.lo, count.hi);
    for (int i = 0; i < n; ++i) {
        Adhesion adhesion;
        adhesion.place.segment = where.segments[random.choose(where.share)];
        // The position along the segment is set once the anatomy is known.
        adhesion.place.position = random.uniform();
        adhesion.place.clockAngle =
            quantity::clockAngle.quantise(random.integer(0, 359) * quantity::clockAngle.siPerUnit);
        adhesions.push_back(adhesion);
    }
}
}  // namespace

void sampleHistory(const Statistics& stats, const Patient& patient, Random& random, History& history,
                   std::vector<Adhesion>& adhesions)
{
    history.priorAbdominalSurgery = random.chance(stats.priorSurgery.value);
    history.hysterectomy = patient.sex == Sex::Female && random.chance(stats.hysterectomyRate(patient.age));
    history.anticoagulant = Anticoagulant::None;
    if (random.chance(stats.anticoagulantRate(patient.age))) {
        history.anticoagulant = static_cast<Anticoagulant>(1 + random.choose(stats.anticoagulantTypeShare));
    }
    adhesions.clear();
    if (history.hysterectomy) {
        addAdhesions(stats.hysterectomyAdhesionCount, stats.hysterectomyAdhesionSegments, random, adhesions);
    }
    if (history.priorAbdominalSurgery && random.chance(stats.otherSurgeryAdhesionChance)) {
        addAdhesions(stats.otherAdhesionCount, stats.otherAdhesionSegments, random, adhesions);
    }
}

}  // namespace colonosim::cases
