#pragma once
/// \file
/// Stage 5 of a case: lesions, diverticula, colitis and hemorrhoids, with
/// the probabilities of the patient's age and sex (data file groups adenoma,
/// cancer, serrated, lipoma, diverticulosis, colitis, hemorrhoids).
///
/// Adenomas: present with the prevalence of the age band and sex; their
/// number follows a zero-truncated Poisson law with the published mean. The
/// location pattern (only proximal, only distal, both) is drawn given the
/// number: one adenoma is proximal with r = p_op / (p_op + p_od); two or more
/// are in both regions with p_both / P(n >= 2), otherwise in one region (again
/// with r), which reproduces the three published shares. Size class, size,
/// advanced histology given size, histology and morphology are drawn per
/// lesion; flat lesions >= 10 mm are laterally spreading tumours. A lesion's
/// segment is chosen in proportion to the lengths of its region's segments,
/// its position along the segment and its clock angle uniformly.
///
/// Appearance follows the histology (colour, surface, NICE class); the miss
/// rate is the van Rijn rate of its size as the pedunculated baseline, with
/// the odds ratio of its morphology applied.

#include "case_generator/Case.h"
#include "case_generator/Random.h"
#include "case_generator/Statistics.h"

namespace colonosim::cases {

/// Needs the patient and the anatomy (lengths).
void samplePathology(const Statistics& stats, Random& random, Case& c);
/// Colour, surface, NICE class and miss rate of a lesion from its histology,
/// Paris class and size (deterministic).
void describeAppearance(const Statistics& stats, Lesion& lesion);
/// A lesion cannot be larger than the lumen's circumference; caps the size
/// after the diameters are tuned.
void fitLesionsToLumen(Case& c);

}  // namespace colonosim::cases
