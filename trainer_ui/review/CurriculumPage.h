#pragma once
/// \file
/// Curriculum import: the administrator names a curriculum file, the
/// curricula reader validates it (the rules of schema/curriculum.xsd, the
/// case-constraint grammar, prerequisites), and a valid file is stored in the
/// records under its name. A refused file lists every problem as a sentence
/// with its line number; nothing is stored then.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;

namespace colonosim::app {

class CurriculumPage : public QWidget {
    Q_OBJECT
public:
    explicit CurriculumPage(AppContext& context, QWidget* parent = nullptr);

    /// "file.xml:12: message" as a person reads it: "Line 12: message".
    [[nodiscard]] static QString sentence(const std::string& error);

private:
    void import();

    AppContext& m_context;
    QLineEdit* m_path;
    QListWidget* m_errors;
    QLabel* m_status;
};

}  // namespace colonosim::app
