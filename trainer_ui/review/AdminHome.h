#pragma once
/// \file
/// The administrator's home screen: users and cohorts (add, assign, reset a
/// password), curriculum import with validation, certification-rule status
/// per trainee with the export of certification reports (PDF, CSV, xAPI) for
/// one trainee or a whole cohort, and database backup. Everything goes
/// through AppContext::records, which refuses what the person may not do.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QTabWidget;

namespace colonosim::app {

class UsersPage;
class CurriculumPage;
class CertificationPage;
class BackupPage;

class AdminHome : public QWidget {
    Q_OBJECT
public:
    explicit AdminHome(AppContext& context, QWidget* parent = nullptr);

private:
    AppContext& m_context;
    QTabWidget* m_tabs;
    UsersPage* m_users;
    CurriculumPage* m_curriculum;
    CertificationPage* m_certification;
    BackupPage* m_backup;
};

}  // namespace colonosim::app
