#pragma once
/// \file
/// A curriculum file (schema/curriculum.xsd; the core one is
/// colonoscopy-core.xml): modules ordered easy to hard, each with tasks. A
/// task carries its instructions and learning objectives, the case
/// constraints it hands to the case generator (its grammar, checked here),
/// the benchmark set it is scored against, its prerequisites, the time
/// limit, whether it can be run yet (tasks that need instruments say why
/// not), and whether the scope-shape view may be shown (shape_view). The reader refuses bad files with
/// `file:line: message`, naming the field, the value and what is allowed.

#include "case_generator/Constraints.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace colonosim::curricula {

struct Task {
    std::string id, title, module, benchmark;
    std::string instructions;
    std::vector<std::string> objectives;
    cases::Constraints constraints;
    std::vector<std::string> prerequisites;
    double maxTime = 900.0;  ///< s
    bool available = true;
    std::string unavailableReason;
    bool shapeView = true;  ///< the scope-shape view (magnetic imager) is shown during the task
};

struct Module {
    std::string id, title;
};

struct Curriculum {
    std::string name;
    int version = 1;
    std::vector<Module> modules;
    std::vector<Task> tasks;  ///< in file order: easy to hard

    [[nodiscard]] const Task* find(const std::string& id) const;
};

struct CurriculumRead {
    std::optional<Curriculum> value;
    std::vector<std::string> errors;
    [[nodiscard]] bool ok() const { return value.has_value(); }
};

/// `label` names the source in messages (a file name).
[[nodiscard]] CurriculumRead parseCurriculum(const std::string& xml, const std::string& label);
[[nodiscard]] CurriculumRead readCurriculumFile(const std::filesystem::path& path);
/// The core curriculum, compiled in (colonoscopy-core.xml).
[[nodiscard]] const std::string& coreCurriculumXml();

}  // namespace colonosim::curricula
