#pragma once
/// \file
/// The administrator's users and cohorts: every user with their role and
/// cohorts; adding a user or a cohort; putting a student into a cohort or
/// assigning an instructor to one; resetting a password. Forms keep what was
/// typed when the records refuse it, and say why.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QStandardItemModel;
class QTableView;

namespace colonosim::app {

class UsersPage : public QWidget {
    Q_OBJECT
public:
    explicit UsersPage(AppContext& context, QWidget* parent = nullptr);
    void refresh();

Q_SIGNALS:
    /// Users or cohorts changed (other pages list them).
    void changed();

private:
    void addUser();
    void addCohort();
    void addToCohort();
    void resetPassword();
    void say(const QString& text, bool error = false);

    AppContext& m_context;
    QStandardItemModel* m_model;
    QTableView* m_table;
    QLineEdit* m_newName;
    QComboBox* m_newRole;
    QLineEdit* m_newPassword;
    QLineEdit* m_cohortName;
    QComboBox* m_memberUser;
    QComboBox* m_memberCohort;
    QComboBox* m_resetUser;
    QLineEdit* m_resetPassword;
    QLabel* m_status;
};

}  // namespace colonosim::app
