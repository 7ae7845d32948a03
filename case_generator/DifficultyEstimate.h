#pragma once
/// \file
/// Stage 7 of a case: the difficulty estimate and the training task.
///
/// Each factor the data file lists ("difficulty.factors": name, points,
/// source) adds its points when present; difficulty = 1 + floor(sum), at most
/// 5. The factors this code can recognise are listed by knownDifficultyFactors();
/// the data file decides which count and how much.
///
/// Task: polypectomy when an adenoma or serrated lesion of 6-25 mm that is
/// not depressed is present (the scene then needs a snare); detection when
/// any lesion is; intubation otherwise.

#include "case_generator/Case.h"
#include "case_generator/Statistics.h"

#include <span>
#include <string_view>

namespace colonosim::cases {

[[nodiscard]] std::span<const std::string_view> knownDifficultyFactors();
/// Whether the named factor is present in the case; false for an unknown name.
[[nodiscard]] bool difficultyFactorPresent(std::string_view name, const Case& c, const Statistics& stats);
[[nodiscard]] Difficulty estimateDifficulty(const Case& c, const Statistics& stats);
[[nodiscard]] TrainingTask trainingTask(const Case& c);

}  // namespace colonosim::cases
