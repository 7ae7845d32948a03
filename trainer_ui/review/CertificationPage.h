#pragma once
/// \file
/// Certification for the administrator: the certification rule set of record
/// (the active one; import and activate, RuleSetBox.h), the status of every
/// rule of the active set for a chosen trainee, and the export of reports (signed PDF, CSV,
/// xAPI) for one trainee or a whole cohort. Exports run off the UI thread
/// with a progress bar and Cancel; a cancelled or failed export leaves no
/// file behind (reports/CohortExport.h).

#include "trainer_ui/app/AppContext.h"

#include "trainer_ui/review/LazyPage.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QStandardItemModel;
class QTableView;

namespace colonosim::app {

class BackgroundJob;
class RuleSetBox;

class CertificationPage : public LazyPage {
    Q_OBJECT
public:
    explicit CertificationPage(AppContext& context, QWidget* parent = nullptr);

protected:
    void reload() override;

private:
    void showRules();
    void startExport();
    void suggestPath();
    void say(const QString& text, bool error = false);

    AppContext& m_context;
    RuleSetBox* m_ruleSet;
    QComboBox* m_trainee;
    QStandardItemModel* m_rules;
    QTableView* m_table;
    QLabel* m_ruleSummary;
    QComboBox* m_scope;
    QComboBox* m_format;
    QLineEdit* m_path;
    QPushButton* m_export;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    BackgroundJob* m_job;
};

}  // namespace colonosim::app
