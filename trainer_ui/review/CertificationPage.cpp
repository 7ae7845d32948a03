#include "trainer_ui/review/CertificationPage.h"

#include "db/Cohorts.h"
#include "trainer_ui/reports/CohortExport.h"
#include "trainer_ui/reports/ProgressReport.h"
#include "trainer_ui/review/BackgroundJob.h"
#include "trainer_ui/review/ReadableTrainees.h"
#include "trainer_ui/review/RuleSetBox.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

#include <cmath>

namespace colonosim::app {

CertificationPage::CertificationPage(AppContext& context, QWidget* parent)
    : LazyPage(parent), m_context(context), m_ruleSet(new RuleSetBox(context)), m_trainee(new QComboBox),
      m_rules(new QStandardItemModel(this)), m_table(new QTableView), m_ruleSummary(new QLabel),
      m_scope(new QComboBox), m_format(new QComboBox), m_path(new QLineEdit),
      m_export(new QPushButton(QStringLiteral("Export"))),
      m_cancel(new QPushButton(QStringLiteral("Cancel"))), m_progress(new QProgressBar), m_status(new QLabel),
      m_job(new BackgroundJob(this))
{
    m_trainee->setObjectName(QStringLiteral("certTrainee"));
    m_table->setObjectName(QStringLiteral("ruleTable"));
    m_ruleSummary->setObjectName(QStringLiteral("ruleSummary"));
    m_scope->setObjectName(QStringLiteral("exportScope"));
    m_format->setObjectName(QStringLiteral("exportFormat"));
    m_path->setObjectName(QStringLiteral("exportPath"));
    m_export->setObjectName(QStringLiteral("exportButton"));
    m_cancel->setObjectName(QStringLiteral("cancelExportButton"));
    m_progress->setObjectName(QStringLiteral("exportProgress"));
    m_status->setObjectName(QStringLiteral("exportStatus"));
    m_status->setWordWrap(true);
    m_ruleSummary->setWordWrap(true);
    m_table->setModel(m_rules);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_format->addItem(QStringLiteral("PDF certification report (signed)"), QStringLiteral("pdf"));
    m_format->addItem(QStringLiteral("CSV, every metric of every session"), QStringLiteral("csv"));
    m_format->addItem(QStringLiteral("xAPI statements (JSON)"), QStringLiteral("xapi"));
    m_cancel->setEnabled(false);
    m_progress->setValue(0);

    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(QStringLiteral("Trainee:")));
    top->addWidget(m_trainee, 1);
    top->addStretch(2);

    auto* exportBox = new QGroupBox(QStringLiteral("Export reports"));
    auto* form = new QFormLayout(exportBox);
    form->addRow(QStringLiteral("For:"), m_scope);
    form->addRow(QStringLiteral("Format:"), m_format);
    form->addRow(QStringLiteral("Save as:"), m_path);
    auto* run = new QHBoxLayout;
    run->addWidget(m_export);
    run->addWidget(m_progress, 1);
    run->addWidget(m_cancel);
    form->addRow(run);
    form->addRow(m_status);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_ruleSet);
    layout->addLayout(top);
    layout->addWidget(m_ruleSummary);
    layout->addWidget(m_table, 1);
    layout->addWidget(exportBox);

    connect(m_ruleSet, &RuleSetBox::changed, this, &CertificationPage::showRules);
    connect(m_trainee, &QComboBox::currentIndexChanged, this, &CertificationPage::showRules);
    connect(m_scope, &QComboBox::currentIndexChanged, this, &CertificationPage::suggestPath);
    connect(m_format, &QComboBox::currentIndexChanged, this, &CertificationPage::suggestPath);
    connect(m_export, &QPushButton::clicked, this, &CertificationPage::startExport);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        m_job->cancel();
        say(QStringLiteral("Cancelling…"));
    });
    connect(m_job, &BackgroundJob::progressed, this, [this](int done, int total) {
        m_progress->setMaximum(total);
        m_progress->setValue(done);
    });
    connect(m_job, &BackgroundJob::finished, this, [this](bool cancelled, const QString& error) {
        m_export->setEnabled(true);
        m_cancel->setEnabled(false);
        if (!error.isEmpty()) {
            say(QStringLiteral("Nothing was exported: %1").arg(error), true);
        } else if (cancelled) {
            m_progress->setValue(0);
            say(QStringLiteral("Export cancelled; no file was written."));
        } else {
            say(QStringLiteral("Written: %1").arg(m_path->text()));
        }
    });
}

void CertificationPage::say(const QString& text, bool error)
{
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c") : QString());
    m_status->setText(text);
}

void CertificationPage::reload()
{
    const QString trainee = m_trainee->currentText();
    const QString scope = m_scope->currentText();
    {
        const QSignalBlocker blockTrainee(m_trainee);
        const QSignalBlocker blockScope(m_scope);
        m_trainee->clear();
        m_scope->clear();
        for (const std::string& t : readableTrainees(m_context.records, m_context.actor)) {
            m_trainee->addItem(QString::fromStdString(t));
            m_scope->addItem(QStringLiteral("trainee %1").arg(QString::fromStdString(t)),
                             QStringList{QStringLiteral("trainee"), QString::fromStdString(t)});
        }
        for (const db::CohortRow& c : db::readableCohorts(m_context.database, m_context.actor)) {
            QStringList item{QStringLiteral("cohort"), QString::fromStdString(c.name)};
            for (const std::string& m : c.members) {
                item << QString::fromStdString(m);
            }
            m_scope->addItem(QStringLiteral("cohort %1 (%2 trainees)")
                                 .arg(QString::fromStdString(c.name))
                                 .arg(c.members.size()),
                             item);
        }
        m_trainee->setCurrentIndex(std::max(0, m_trainee->findText(trainee)));
        m_scope->setCurrentIndex(std::max(0, m_scope->findText(scope)));
    }
    m_ruleSet->reload();
    showRules();
    suggestPath();
}

void CertificationPage::showRules()
{
    m_rules->clear();
    m_rules->setHorizontalHeaderLabels({QStringLiteral("Status"), QStringLiteral("Rule"),
                                        QStringLiteral("Observed"), QStringLiteral("Sessions"),
                                        QStringLiteral("Source")});
    const std::string trainee = m_trainee->currentText().toStdString();
    if (trainee.empty()) {
        m_ruleSummary->setText(QStringLiteral("There are no trainees yet."));
        return;
    }
    try {
        const nlohmann::json progress =
            reports::progressReport(m_context.database, m_context.records, m_context.actor, trainee);
        int met = 0;
        int rules = 0;
        for (const auto& r : progress["certification"]) {
            const bool ok = r["met"].get<bool>();
            auto* status = new QStandardItem(ok ? QStringLiteral("met") : QStringLiteral("not met"));
            status->setForeground(ok ? QColor(20, 120, 40) : QColor(180, 30, 30));
            m_rules->appendRow(
                {status, new QStandardItem(QString::fromStdString(r["description"].get<std::string>())),
                 new QStandardItem(QString::fromStdString(reports::observedText(
                     r["observed"].is_null() ? std::nan("") : r["observed"].get<double>()))),
                 new QStandardItem(QString::fromStdString(reports::sessionsText(r))),
                 new QStandardItem(QString::fromStdString(r["source"].get<std::string>()))});
            ++rules;
            met += ok ? 1 : 0;
        }
        m_ruleSummary->setText(
            QStringLiteral("%1: %2 completed session(s); %3 of %4 certification rules met (rule set %5).")
                .arg(QString::fromStdString(trainee))
                .arg(progress["completed_sessions"].get<int>())
                .arg(met)
                .arg(rules)
                .arg(QString::fromStdString(reports::ruleSetLabel(progress))));
        m_table->resizeColumnsToContents();
        m_table->setColumnWidth(1, std::min(m_table->columnWidth(1), 420));
    } catch (const std::exception& e) {
        m_ruleSummary->setText(QString::fromStdString(e.what()));
    }
}

void CertificationPage::suggestPath()
{
    const QStringList scope = m_scope->currentData().toStringList();
    if (scope.size() < 2) {
        return;
    }
    const QString format = m_format->currentData().toString();
    QString name = QStringLiteral("%1-%2").arg(scope[0], scope[1]);
    if (format == QStringLiteral("csv")) {
        name += QStringLiteral(".csv");
    } else if (format == QStringLiteral("xapi")) {
        name += QStringLiteral(".xapi.json");
    } else if (scope[0] == QStringLiteral("trainee")) {
        name += QStringLiteral(".pdf");
    } else {
        name += QStringLiteral("-certificates");  // a folder, one PDF per trainee
    }
    m_path->setText(QString::fromStdString((m_context.exportDir / name.toStdString()).string()));
}

void CertificationPage::startExport()
{
    const QStringList scope = m_scope->currentData().toStringList();
    const std::string out = m_path->text().trimmed().toStdString();
    if (scope.size() < 2 || out.empty()) {
        say(QStringLiteral("Choose a trainee or a cohort, and where to save the export."), true);
        return;
    }
    const auto format = *reports::parseFormat(m_format->currentData().toString().toStdString());
    std::vector<std::string> trainees;
    if (scope[0] == QStringLiteral("trainee")) {
        trainees.push_back(scope[1].toStdString());
    } else {
        for (qsizetype k = 2; k < scope.size(); ++k) {
            trainees.push_back(scope[k].toStdString());
        }
    }
    if (trainees.empty()) {
        say(QStringLiteral("Cohort %1 has no trainees: there is nothing to export.").arg(scope[1]), true);
        return;
    }
    const bool single = scope[0] == QStringLiteral("trainee");
    const std::filesystem::path file = m_context.database.path();
    const db::Actor actor = m_context.actor;
    m_progress->setRange(0, static_cast<int>(trainees.size()));
    m_progress->setValue(0);
    const bool started = m_job->start([=](std::stop_token stop, const std::function<void(int, int)>& report) {
        db::Database database(file);
        db::Records records(database);
        if (single) {
            if (std::filesystem::exists(out)) {
                throw std::runtime_error(out + " exists already: choose another name, nothing was replaced");
            }
            const std::string bytes = reports::traineeReport(format, database, records, actor, trainees[0]);
            if (stop.stop_requested()) {
                return false;
            }
            reports::writeFileWhole(out, bytes);
            report(1, 1);
            return true;
        }
        return reports::exportCohort(format, database, records, actor, trainees, out, stop, report) ==
               reports::ExportOutcome::Written;
    });
    if (started) {
        m_export->setEnabled(false);
        m_cancel->setEnabled(true);
        say(QStringLiteral("Exporting %1 trainee(s)…").arg(trainees.size()));
    }
}

}  // namespace colonosim::app
