#include "trainer_ui/review/RuleSetBox.h"

#include "db/CertificationRules.h"
#include "trainer_ui/reports/TraineeReport.h"
#include "trainer_ui/review/CurriculumPage.h"

#include <QComboBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>

#include <algorithm>
#include <filesystem>

namespace colonosim::app {

namespace {

QString describe(const db::RuleSetVersion& v)
{
    return QStringLiteral("%1, version %2 (%3)")
        .arg(QString::fromStdString(v.name))
        .arg(v.version)
        .arg(v.importedBy.empty() ? QStringLiteral("shipped with colonosim")
                                  : QStringLiteral("imported by %1 on %2")
                                        .arg(QString::fromStdString(v.importedBy),
                                             QString::fromStdString(v.importedAt.substr(0, 10))));
}

}  // namespace

RuleSetBox::RuleSetBox(AppContext& context, QWidget* parent)
    : QGroupBox(QStringLiteral("Certification rule set"), parent), m_context(context), m_active(new QLabel),
      m_versions(new QComboBox), m_path(new QLineEdit), m_status(new QLabel), m_problems(new QListWidget)
{
    m_active->setObjectName(QStringLiteral("activeRuleSet"));
    m_versions->setObjectName(QStringLiteral("ruleSetVersions"));
    m_path->setObjectName(QStringLiteral("ruleSetPath"));
    m_path->setPlaceholderText(QStringLiteral("certification rule set file (.xml)"));
    m_status->setObjectName(QStringLiteral("ruleSetStatus"));
    m_status->setWordWrap(true);
    m_problems->setObjectName(QStringLiteral("ruleSetProblems"));
    m_problems->setWordWrap(true);
    m_problems->hide();
    QFont bold = m_active->font();
    bold.setBold(true);
    m_active->setFont(bold);
    auto* activateButton = new QPushButton(QStringLiteral("Activate"));
    activateButton->setObjectName(QStringLiteral("activateRuleSetButton"));
    auto* browse = new QPushButton(QStringLiteral("Browse…"));
    auto* importButton = new QPushButton(QStringLiteral("Validate and import"));
    importButton->setObjectName(QStringLiteral("importRuleSetButton"));

    auto* grid = new QGridLayout(this);
    grid->addWidget(new QLabel(QStringLiteral("Active:")), 0, 0);
    grid->addWidget(m_active, 0, 1, 1, 3);
    grid->addWidget(new QLabel(QStringLiteral("Stored:")), 1, 0);
    grid->addWidget(m_versions, 1, 1, 1, 2);
    grid->addWidget(activateButton, 1, 3);
    grid->addWidget(new QLabel(QStringLiteral("Import:")), 2, 0);
    grid->addWidget(m_path, 2, 1);
    grid->addWidget(browse, 2, 2);
    grid->addWidget(importButton, 2, 3);
    grid->addWidget(m_status, 3, 0, 1, 4);
    grid->addWidget(m_problems, 4, 0, 1, 4);
    grid->setColumnStretch(1, 1);

    connect(activateButton, &QPushButton::clicked, this, &RuleSetBox::activate);
    connect(importButton, &QPushButton::clicked, this, &RuleSetBox::import);
    connect(m_path, &QLineEdit::returnPressed, this, &RuleSetBox::import);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getOpenFileName(
            this, QStringLiteral("Certification rule set"),
            QString::fromStdString(m_context.exportDir.string()), QStringLiteral("Rule sets (*.xml)"));
        if (!file.isEmpty()) {
            m_path->setText(file);
        }
    });
    reload();
}

void RuleSetBox::reload()
{
    db::CertificationRules rules(m_context.database);
    m_versions->clear();
    try {
        for (const db::RuleSetVersion& v : rules.versions(m_context.actor)) {
            m_versions->addItem(describe(v) + (v.active ? QStringLiteral(": active") : QString()), v.version);
            if (v.active) {
                m_versions->setCurrentIndex(m_versions->count() - 1);
                m_active->setText(describe(v));
            }
        }
    } catch (const std::exception& e) {
        say(QString::fromStdString(e.what()), true);
    }
}

void RuleSetBox::say(const QString& text, bool error)
{
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c") : QString());
    m_status->setText(text);
}

void RuleSetBox::import()
{
    m_problems->clear();
    m_problems->hide();
    const std::string path = m_path->text().trimmed().toStdString();
    if (path.empty()) {
        say(QStringLiteral("Name the rule set file to import first."), true);
        return;
    }
    const std::optional<std::string> xml = reports::readFileWhole(path);
    if (!xml) {
        say(QStringLiteral("%1 cannot be read: check the name and that the file exists.")
                .arg(QString::fromStdString(path)),
            true);
        return;
    }
    try {
        const db::RuleSetVersion stored =
            db::CertificationRules(m_context.database)
                .import(m_context.actor, *xml, std::filesystem::path(path).filename().string());
        reload();
        say(QStringLiteral("Imported %1. It is stored, not yet active: choose it above and press Activate.")
                .arg(describe(stored)),
            false);
    } catch (const db::RuleSetRejected& rejected) {
        for (const std::string& e : rejected.errors()) {
            m_problems->addItem(CurriculumPage::sentence(e));
        }
        // As tall as its problems, up to four of them; the rest scroll.
        const int rows = std::min(m_problems->count(), 4);
        m_problems->setFixedHeight(rows * m_problems->sizeHintForRow(0) + 2 * m_problems->frameWidth() + 4);
        m_problems->show();
        say(QStringLiteral("%1 was not imported: %2 problem(s) to fix.")
                .arg(QString::fromStdString(path))
                .arg(rejected.errors().size()),
            true);
    } catch (const std::exception& e) {
        say(QStringLiteral("%1 was not imported: %2.").arg(QString::fromStdString(path), e.what()), true);
    }
}

void RuleSetBox::activate()
{
    if (m_versions->currentIndex() < 0) {
        say(QStringLiteral("There is no stored rule set to activate."), true);
        return;
    }
    const int version = m_versions->currentData().toInt();
    try {
        db::CertificationRules(m_context.database).activate(m_context.actor, version);
        reload();
        say(QStringLiteral("Version %1 is now the active rule set: certification status is judged by it.")
                .arg(version),
            false);
        Q_EMIT changed();
    } catch (const std::exception& e) {
        say(QStringLiteral("Version %1 was not activated: %2.").arg(version).arg(e.what()), true);
    }
}

}  // namespace colonosim::app
