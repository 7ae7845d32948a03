#include "curricula/Progression.h"

namespace colonosim::curricula {

std::string stateName(TaskState state)
{
    switch (state) {
    case TaskState::Locked: return "locked";
    case TaskState::Unlocked: return "unlocked";
    case TaskState::Proficient: return "proficient";
    case TaskState::Unavailable: return "unavailable";
    }
    return "locked";
}

std::map<std::string, TaskState> progression(const Curriculum& curriculum,
                                             const std::vector<Attempt>& attempts)
{
    std::map<std::string, TaskState> state;
    auto refresh = [&] {
        for (const Task& task : curriculum.tasks) {
            TaskState& s = state[task.id];
            if (!task.available) {
                s = TaskState::Unavailable;
                continue;
            }
            if (s == TaskState::Proficient) {
                continue;
            }
            bool ready = true;
            for (const std::string& p : task.prerequisites) {
                ready = ready && state[p] == TaskState::Proficient;
            }
            s = ready ? TaskState::Unlocked : TaskState::Locked;
        }
    };
    refresh();
    std::map<std::string, int> run;  // consecutive met attempts per task
    for (const Attempt& a : attempts) {
        const auto it = state.find(a.task);
        if (it == state.end() || it->second != TaskState::Unlocked) {
            continue;
        }
        int& n = run[a.task];
        n = a.benchmarkMet ? n + 1 : 0;
        if (n >= kConsecutiveForProficiency) {
            it->second = TaskState::Proficient;
            refresh();
        }
    }
    return state;
}

}  // namespace colonosim::curricula
