#pragma once
/// \file
/// Stage 6 of a case: bowel preparation and insufflation.
///
/// Preparation: a class from Calderwood 2014 (all segments >= 2; total 3-5;
/// total 0-2; the rest), then a triple of BBPS segment scores (right,
/// transverse, left; 0-3 each) uniformly among the 64 triples of that class.
/// Residual stool (fraction of mucosa) and fluid (volume) are uniform over
/// the ranges the data file gives for each score. Insufflation: a compliance
/// factor uniform over its range; working pressure = reference / compliance.

#include "case_generator/Case.h"
#include "case_generator/Random.h"
#include "case_generator/Statistics.h"

namespace colonosim::cases {

void sampleEnvironment(const Statistics& stats, Random& random, Environment& environment);
/// The preparation class (0-3, data file order) of three segment scores.
[[nodiscard]] int preparationClass(int right, int transverse, int left);

}  // namespace colonosim::cases
