#pragma once
/// \file
/// The case library with the generator. The instructor sets constraints
/// (age, sex, difficulty) and a seed, generates a case and reads its preview
/// (history and findings), saves it to the records, and assigns a saved case
/// to a trainee or a cohort. A library of N cases (seeds s..s+N-1, same
/// constraints) is generated and saved off the UI thread, with progress and
/// Cancel; what was saved before a cancel stays saved.

#include "case_generator/Case.h"
#include "trainer_ui/app/AppContext.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTextBrowser;

namespace colonosim::cases {
struct Constraints;
}

namespace colonosim::app {

class BackgroundJob;

class CaseLibraryPage : public QWidget {
    Q_OBJECT
public:
    explicit CaseLibraryPage(AppContext& context, QWidget* parent = nullptr);
    void refresh();

private:
    [[nodiscard]] cases::Constraints constraints() const;
    void generate();
    void save();
    void assign();
    void generateLibrary();
    void say(const QString& text, bool error = false);

    AppContext& m_context;
    std::optional<cases::Case> m_generated;
    QSpinBox* m_ageMin;
    QSpinBox* m_ageMax;
    QComboBox* m_sex;
    QSpinBox* m_difficultyMin;
    QSpinBox* m_difficultyMax;
    QSpinBox* m_seed;
    QTextBrowser* m_preview;
    QPushButton* m_save;
    QListWidget* m_cases;
    QComboBox* m_target;
    QPushButton* m_assign;
    QSpinBox* m_count;
    QPushButton* m_generateLibrary;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    BackgroundJob* m_job;
};

}  // namespace colonosim::app
