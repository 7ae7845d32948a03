#include "trainer_ui/review/UsersPage.h"

#include "db/Cohorts.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

#include <map>

namespace colonosim::app {

namespace {

QLineEdit* field(const QString& name, const QString& placeholder, bool secret = false)
{
    auto* edit = new QLineEdit;
    edit->setObjectName(name);
    edit->setPlaceholderText(placeholder);
    if (secret) {
        edit->setEchoMode(QLineEdit::Password);
    }
    return edit;
}

QComboBox* combo(const QString& name)
{
    auto* box = new QComboBox;
    box->setObjectName(name);
    box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    return box;
}

QPushButton* button(const QString& name, const QString& text)
{
    auto* b = new QPushButton(text);
    b->setObjectName(name);
    return b;
}

}  // namespace

UsersPage::UsersPage(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context), m_model(new QStandardItemModel(this)), m_table(new QTableView),
      m_newName(field(QStringLiteral("newUserName"), QStringLiteral("name, 1-64 characters"))),
      m_newRole(combo(QStringLiteral("newUserRole"))),
      m_newPassword(field(QStringLiteral("newUserPassword"), QStringLiteral("at least 8 characters"), true)),
      m_cohortName(field(QStringLiteral("newCohortName"), QStringLiteral("cohort name"))),
      m_memberUser(combo(QStringLiteral("memberUser"))),
      m_memberCohort(combo(QStringLiteral("memberCohort"))), m_resetUser(combo(QStringLiteral("resetUser"))),
      m_resetPassword(field(QStringLiteral("resetPassword"),
                            QStringLiteral("new password, at least 8 "
                                           "characters"),
                            true)),
      m_status(new QLabel)
{
    m_table->setObjectName(QStringLiteral("userTable"));
    m_status->setObjectName(QStringLiteral("usersStatus"));
    m_status->setWordWrap(true);
    m_table->setModel(m_model);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setStretchLastSection(true);
    for (const db::Role role : {db::Role::Student, db::Role::Instructor, db::Role::Administrator}) {
        m_newRole->addItem(QString::fromStdString(db::roleName(role)), static_cast<int>(role));
    }

    auto* addUserButton = button(QStringLiteral("addUserButton"), QStringLiteral("Add user"));
    auto* addCohortButton = button(QStringLiteral("addCohortButton"), QStringLiteral("Add cohort"));
    auto* memberButton = button(QStringLiteral("addToCohortButton"), QStringLiteral("Add to cohort"));
    auto* resetButton = button(QStringLiteral("resetPasswordButton"), QStringLiteral("Set password"));

    auto* userBox = new QGroupBox(QStringLiteral("New user"));
    auto* userForm = new QFormLayout(userBox);
    userForm->addRow(QStringLiteral("Name:"), m_newName);
    userForm->addRow(QStringLiteral("Role:"), m_newRole);
    userForm->addRow(QStringLiteral("Password:"), m_newPassword);
    userForm->addRow(addUserButton);

    auto* cohortBox = new QGroupBox(QStringLiteral("Cohorts"));
    auto* cohortForm = new QFormLayout(cohortBox);
    auto* newCohort = new QHBoxLayout;
    newCohort->addWidget(m_cohortName, 1);
    newCohort->addWidget(addCohortButton);
    cohortForm->addRow(QStringLiteral("New cohort:"), newCohort);
    cohortForm->addRow(QStringLiteral("User:"), m_memberUser);
    cohortForm->addRow(QStringLiteral("Cohort:"), m_memberCohort);
    cohortForm->addRow(memberButton);
    auto* note = new QLabel(QStringLiteral("A student joins the cohort; an instructor is assigned to it and "
                                           "reads its students' records."));
    note->setWordWrap(true);
    cohortForm->addRow(note);

    auto* resetBox = new QGroupBox(QStringLiteral("Reset a password"));
    auto* resetForm = new QFormLayout(resetBox);
    resetForm->addRow(QStringLiteral("User:"), m_resetUser);
    resetForm->addRow(QStringLiteral("New password:"), m_resetPassword);
    resetForm->addRow(resetButton);

    auto* forms = new QVBoxLayout;
    forms->addWidget(userBox);
    forms->addWidget(cohortBox);
    forms->addWidget(resetBox);
    forms->addStretch(1);
    auto* columns = new QHBoxLayout;
    columns->addWidget(m_table, 3);
    columns->addLayout(forms, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(m_status);

    connect(addUserButton, &QPushButton::clicked, this, &UsersPage::addUser);
    connect(addCohortButton, &QPushButton::clicked, this, &UsersPage::addCohort);
    connect(memberButton, &QPushButton::clicked, this, &UsersPage::addToCohort);
    connect(resetButton, &QPushButton::clicked, this, &UsersPage::resetPassword);
    refresh();
}

void UsersPage::say(const QString& text, bool error)
{
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c") : QString());
    m_status->setText(text);
}

void UsersPage::refresh()
{
    const std::vector<db::UserRow> users = m_context.records.listUsers(m_context.actor);
    const std::vector<db::CohortRow> cohorts = db::readableCohorts(m_context.database, m_context.actor);
    std::map<std::string, QStringList> cohortsOf;
    for (const db::CohortRow& c : cohorts) {
        for (const std::string& m : c.members) {
            cohortsOf[m] << QString::fromStdString(c.name);
        }
        for (const std::string& i : c.instructors) {
            cohortsOf[i] << QStringLiteral("%1 (instructor)").arg(QString::fromStdString(c.name));
        }
    }
    m_model->clear();
    m_model->setHorizontalHeaderLabels({QStringLiteral("User"), QStringLiteral("Role"),
                                        QStringLiteral("Created"), QStringLiteral("Cohorts")});
    const QString memberUser = m_memberUser->currentText();
    const QString memberCohort = m_memberCohort->currentText();
    const QString resetUser = m_resetUser->currentText();
    m_memberUser->clear();
    m_memberCohort->clear();
    m_resetUser->clear();
    for (const db::UserRow& u : users) {
        const QString name = QString::fromStdString(u.name);
        m_model->appendRow({new QStandardItem(name),
                            new QStandardItem(QString::fromStdString(db::roleName(u.role))),
                            new QStandardItem(QString::fromStdString(u.createdAt).left(10)),
                            new QStandardItem(cohortsOf[u.name].join(QStringLiteral(", ")))});
        if (u.role != db::Role::Administrator) {
            m_memberUser->addItem(name);
        }
        m_resetUser->addItem(name);
    }
    for (const db::CohortRow& c : cohorts) {
        m_memberCohort->addItem(QString::fromStdString(c.name));
    }
    m_memberUser->setCurrentIndex(std::max(0, m_memberUser->findText(memberUser)));
    m_memberCohort->setCurrentIndex(std::max(0, m_memberCohort->findText(memberCohort)));
    m_resetUser->setCurrentIndex(std::max(0, m_resetUser->findText(resetUser)));
    m_table->resizeColumnsToContents();
}

void UsersPage::addUser()
{
    const std::string name = m_newName->text().trimmed().toStdString();
    const auto role = static_cast<db::Role>(m_newRole->currentData().toInt());
    try {
        m_context.records.addUser(m_context.actor, name, role, m_newPassword->text().toStdString());
        m_newName->clear();
        m_newPassword->clear();
        refresh();
        say(QStringLiteral("%1 (%2) was added.")
                .arg(QString::fromStdString(name), QString::fromStdString(db::roleName(role))));
        Q_EMIT changed();
    } catch (const std::exception& e) {
        say(QStringLiteral("The user was not added: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void UsersPage::addCohort()
{
    const std::string name = m_cohortName->text().trimmed().toStdString();
    try {
        m_context.records.addCohort(m_context.actor, name);
        m_cohortName->clear();
        refresh();
        m_memberCohort->setCurrentIndex(m_memberCohort->findText(QString::fromStdString(name)));
        say(QStringLiteral("Cohort %1 was added.").arg(QString::fromStdString(name)));
        Q_EMIT changed();
    } catch (const std::exception& e) {
        say(QStringLiteral("The cohort was not added: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void UsersPage::addToCohort()
{
    const std::string user = m_memberUser->currentText().toStdString();
    const std::string cohort = m_memberCohort->currentText().toStdString();
    if (user.empty() || cohort.empty()) {
        say(QStringLiteral("Choose a user and a cohort first (add a cohort if there is none)."), true);
        return;
    }
    try {
        bool instructor = false;
        for (const db::UserRow& u : m_context.records.listUsers(m_context.actor)) {
            instructor = instructor || (u.name == user && u.role == db::Role::Instructor);
        }
        if (instructor) {
            m_context.records.assignInstructor(m_context.actor, cohort, user);
        } else {
            m_context.records.addMember(m_context.actor, cohort, user);
        }
        refresh();
        say(QStringLiteral("%1 %2 cohort %3.")
                .arg(QString::fromStdString(user),
                     instructor ? QStringLiteral("now teaches") : QStringLiteral("is now in"),
                     QString::fromStdString(cohort)));
        Q_EMIT changed();
    } catch (const std::exception& e) {
        say(QStringLiteral("Nothing changed: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void UsersPage::resetPassword()
{
    const std::string user = m_resetUser->currentText().toStdString();
    try {
        m_context.records.setPassword(m_context.actor, user, m_resetPassword->text().toStdString());
        m_resetPassword->clear();
        say(QStringLiteral("The password of %1 was changed; tell them the new one in person.")
                .arg(QString::fromStdString(user)));
    } catch (const std::exception& e) {
        say(QStringLiteral("The password was not changed: %1").arg(QString::fromStdString(e.what())), true);
    }
}

}  // namespace colonosim::app
