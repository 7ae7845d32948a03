#pragma once
/// \file
/// Database backup: an online copy of the records (SQLite's backup API,
/// consistent while others keep writing) to a file the administrator names.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QLabel;
class QLineEdit;

namespace colonosim::app {

class BackupPage : public QWidget {
    Q_OBJECT
public:
    explicit BackupPage(AppContext& context, QWidget* parent = nullptr);

private:
    void backup();

    AppContext& m_context;
    QLineEdit* m_path;
    QLabel* m_status;
};

}  // namespace colonosim::app
