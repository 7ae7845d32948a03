#pragma once
/// \file
/// Stages 1-3 of a case: the patient (sex, age, name, height, weight, BMI),
/// the indication and the history (prior surgery, hysterectomy and its
/// adhesions, anticoagulants).
///
/// - Sex: Bernoulli(sex_female), or the constrained sex.
/// - Age: an age band by its share times the fraction of its years inside the
///   allowed range, then a whole year uniformly among the allowed years of
///   the band: exactly the population law conditioned on the range.
/// - BMI: log-normal through the obesity and severe-obesity shares of the sex,
///   redrawn outside [bmi.min, bmi.max] and outside the constrained range.
/// - Height: normal by sex, redrawn outside its range; weight = BMI height^2.

#include "case_generator/Case.h"
#include "case_generator/Constraints.h"
#include "case_generator/Random.h"
#include "case_generator/Statistics.h"

namespace colonosim::cases {

/// BMI draws per patient before the BMI range is judged out of reach.
inline constexpr int kBmiDrawBudget = 100000;

/// Draws the patient; false when no BMI in kBmiDrawBudget draws met the range.
[[nodiscard]] bool samplePatient(const Statistics& stats, const Constraints& constraints, Random& random,
                                 Patient& patient);
[[nodiscard]] Indication sampleIndication(const Statistics& stats, Random& random);
/// History and the adhesions it leaves; needs the patient.
void sampleHistory(const Statistics& stats, const Patient& patient, Random& random, History& history,
                   std::vector<Adhesion>& adhesions);

}  // namespace colonosim::cases
