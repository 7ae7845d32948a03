#pragma once
/// \file
/// Stage 4 of a case: the colon's geometry, and (after the pathology) the
/// tuning of wall, mesentery and diameters to BMI, age, sex and pathology.
///
/// Geometry:
/// - total length L ~ normal(mean by sex, sd) (Utano 2021), redrawn outside
///   the sum of the declared segment ranges;
/// - segment i's share ∝ base_i(sex) exp(s_i z_i), normalised to L; a segment
///   that falls outside its declared range is set to the bound it crossed and
///   the rest of L is shared again among the others (so L keeps its law);
/// - diameters log-normal around their medians, mobility by sex (Bernoulli),
///   mesentery heights log-normal with the published mean and SD; each redrawn
///   outside its declared range (geometry::AnatomyParameters).
///
/// Tuning (factors in the data file's "tuning" group, all assumptions):
/// - wall modulus × (1 + a max(0, age - 50)), × the severe-diverticulosis and
///   colitis factors; wall thickness × the same pathology factors;
/// - mesentery thickness = b BMI; mesentery heights × (1 + c max(0, 22 - BMI));
/// - surrounding drag × (1 + d max(0, BMI - 25));
/// - sigmoid diameter × the diverticulosis factor; diameters of the segments
///   with colitis × the colitis factor.
/// Every tuned value is clamped to its declared range.

#include "case_generator/Case.h"
#include "case_generator/Random.h"
#include "case_generator/Statistics.h"

namespace colonosim::cases {

void sampleAnatomy(const Statistics& stats, const Patient& patient, Random& random, CaseAnatomy& anatomy);
/// Sets the tissue and rounds the tuned anatomy; needs the pathology.
void tuneToPatient(const Statistics& stats, Case& c);
/// The segments colitis of this extent involves.
[[nodiscard]] bool colitisInvolves(ColitisExtent extent, Segment segment);

}  // namespace colonosim::cases
