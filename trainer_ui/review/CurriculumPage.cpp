#include "trainer_ui/review/CurriculumPage.h"

#include "curricula/Curriculum.h"
#include "trainer_ui/reports/TraineeReport.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace colonosim::app {

CurriculumPage::CurriculumPage(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context), m_path(new QLineEdit), m_errors(new QListWidget),
      m_status(new QLabel)
{
    m_path->setObjectName(QStringLiteral("curriculumPath"));
    m_path->setPlaceholderText(QStringLiteral("curriculum file (.xml)"));
    m_errors->setObjectName(QStringLiteral("curriculumMessages"));
    m_errors->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("curriculumStatus"));
    m_status->setWordWrap(true);
    auto* browse = new QPushButton(QStringLiteral("Browse…"));
    auto* importButton = new QPushButton(QStringLiteral("Validate and import"));
    importButton->setObjectName(QStringLiteral("importCurriculumButton"));
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(QStringLiteral("File:")));
    row->addWidget(m_path, 1);
    row->addWidget(browse);
    row->addWidget(importButton);
    auto* intro = new QLabel(QStringLiteral(
        "A curriculum file lists modules and tasks (instructions, objectives, case constraints, benchmark "
        "set, prerequisites, time limit). It is checked completely before anything is stored; a curriculum "
        "of the same name is replaced."));
    intro->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(row);
    layout->addWidget(m_status);
    layout->addWidget(m_errors, 1);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getOpenFileName(
            this, QStringLiteral("Curriculum file"), QString::fromStdString(m_context.exportDir.string()),
            QStringLiteral("Curricula (*.xml)"));
        if (!file.isEmpty()) {
            m_path->setText(file);
        }
    });
    connect(importButton, &QPushButton::clicked, this, &CurriculumPage::import);
    connect(m_path, &QLineEdit::returnPressed, this, &CurriculumPage::import);
}

QString CurriculumPage::sentence(const std::string& error)
{
    static const QRegularExpression located(QStringLiteral("^.*:(\\d+): (.*)$"),
                                            QRegularExpression::DotMatchesEverythingOption);
    const QString text = QString::fromStdString(error);
    const QRegularExpressionMatch m = located.match(text);
    if (!m.hasMatch()) {
        return text;
    }
    QString message = m.captured(2);
    if (!message.endsWith(QLatin1Char('.'))) {
        message += QLatin1Char('.');
    }
    return QStringLiteral("Line %1: %2").arg(m.captured(1), message);
}

void CurriculumPage::import()
{
    m_errors->clear();
    m_status->setStyleSheet(QStringLiteral("color: #b01c1c"));
    const std::string path = m_path->text().trimmed().toStdString();
    if (path.empty()) {
        m_status->setText(QStringLiteral("Name the curriculum file to import first."));
        return;
    }
    const std::optional<std::string> xml = reports::readFileWhole(path);
    if (!xml) {
        m_status->setText(QStringLiteral("%1 cannot be read: check the name and that the file exists.")
                              .arg(QString::fromStdString(path)));
        return;
    }
    const curricula::CurriculumRead read =
        curricula::parseCurriculum(*xml, std::filesystem::path(path).filename().string());
    if (!read.ok()) {
        for (const std::string& e : read.errors) {
            m_errors->addItem(sentence(e));
        }
        m_status->setText(QStringLiteral("%1 was not imported: %2 problem(s) to fix.")
                              .arg(QString::fromStdString(path))
                              .arg(read.errors.size()));
        return;
    }
    try {
        m_context.records.storeCurriculum(m_context.actor, read.value->name, *xml);
        int available = 0;
        for (const curricula::Task& t : read.value->tasks) {
            available += t.available ? 1 : 0;
        }
        m_status->setStyleSheet(QString());
        m_status->setText(
            QStringLiteral("Imported curriculum %1, version %2: %3 module(s), %4 task(s) (%5 can "
                           "be run now).")
                .arg(QString::fromStdString(read.value->name))
                .arg(read.value->version)
                .arg(read.value->modules.size())
                .arg(read.value->tasks.size())
                .arg(available));
        for (const curricula::Task& t : read.value->tasks) {
            m_errors->addItem(QStringLiteral("%1 / %2: %3%4")
                                  .arg(QString::fromStdString(t.module), QString::fromStdString(t.id),
                                       QString::fromStdString(t.title),
                                       t.available ? QString()
                                                   : QStringLiteral(" (not yet: %1)")
                                                         .arg(QString::fromStdString(t.unavailableReason))));
        }
    } catch (const std::exception& e) {
        m_status->setText(
            QStringLiteral("The curriculum was not stored: %1").arg(QString::fromStdString(e.what())));
    }
}

}  // namespace colonosim::app
