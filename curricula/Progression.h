#pragma once
/// \file
/// Proficiency-based progression: a task becomes proficient when its
/// benchmark set is met on two consecutive attempts (the rule documented for
/// laparoscopic VR and adopted here as a documented choice; clinical-
/// assessment.md). A task is unlocked when every prerequisite is proficient;
/// attempts count only while their task is unlocked. Tasks that cannot be
/// run yet (no instruments) stay unavailable and never unlock what needs them.

#include "curricula/Curriculum.h"

#include <map>
#include <string>
#include <vector>

namespace colonosim::curricula {

enum class TaskState { Locked, Unlocked, Proficient, Unavailable };
[[nodiscard]] std::string stateName(TaskState state);

inline constexpr int kConsecutiveForProficiency = 2;

/// One completed session, in order.
struct Attempt {
    std::string task;
    bool benchmarkMet = false;
};

[[nodiscard]] std::map<std::string, TaskState> progression(const Curriculum& curriculum,
                                                           const std::vector<Attempt>& attempts);

}  // namespace colonosim::curricula
