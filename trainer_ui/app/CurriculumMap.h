#pragma once
/// \file
/// The student's home: the core curriculum as a map, module by module, each
/// task with its state (locked, open, proficient, not available yet), the
/// student's attempts, and the next task to take marked and selected. States
/// come from the records' progress of the student, and for tasks not yet
/// attempted from the progression rules (curricula/Progression.h) with no
/// attempts, so a new student sees the first task open and the rest locked.

#include "curricula/Curriculum.h"
#include "trainer_ui/app/AppContext.h"

#include <QWidget>

#include <map>
#include <optional>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace colonosim::app {

/// The core curriculum as stored in the records (the compiled-in one when
/// none is stored). Throws std::runtime_error when the stored one cannot be read.
[[nodiscard]] curricula::Curriculum loadCurriculum(AppContext& context);

class CurriculumMap : public QWidget {
    Q_OBJECT
public:
    explicit CurriculumMap(AppContext& context, QWidget* parent = nullptr);

    /// Re-reads the progress (after a session).
    void refresh();
    /// The task marked next, if any.
    [[nodiscard]] std::optional<std::string> nextTask() const { return m_next; }
    /// The state shown for `task`.
    [[nodiscard]] std::string stateOf(const std::string& task) const;

Q_SIGNALS:
    void briefRequested(const QString& task);

private:
    void openSelected();
    void selectionChanged();

    AppContext& m_context;
    curricula::Curriculum m_curriculum;
    std::map<std::string, std::string> m_states;
    std::optional<std::string> m_next;
    QTreeWidget* m_tree = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_preview = nullptr;  ///< the selected task: what it asks, or why it is closed
    QPushButton* m_open = nullptr;
};

}  // namespace colonosim::app
