#include "trainer_ui/app/ResultsScreen.h"

#include "curricula/Progression.h"
#include "scoring/Benchmarks.h"
#include "scoring/MetricDefinitions.h"
#include "trainer_ui/app/MetricAdvice.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace colonosim::app {

namespace {
QString valueText(double value, std::string_view unit)
{
    if (std::isnan(value)) {
        return QObject::tr("not reached");
    }
    QString text = QString::number(value, 'g', 3);
    if (unit != "1") {
        text += QLatin1Char(' ') + QString::fromUtf8(unit.data(), static_cast<qsizetype>(unit.size()));
    }
    return text;
}

/// A metric as a person reads it: its declared label ("Peak handle force").
QString metricLabel(const scoring::MetricDefinition& definition)
{
    return QString::fromUtf8(definition.label.data(), static_cast<qsizetype>(definition.label.size()));
}

QTableWidgetItem* cell(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}
}  // namespace

QString progressionWords(const std::string& state)
{
    if (state == "proficient") {
        return QObject::tr("proficient: the benchmark was met on %1 consecutive attempts")
            .arg(curricula::kConsecutiveForProficiency);
    }
    if (state == "unlocked") {
        return QObject::tr("open: meet the benchmark on %1 consecutive attempts to become proficient")
            .arg(curricula::kConsecutiveForProficiency);
    }
    if (state == "locked") {
        return QObject::tr("locked: its prerequisites are not yet proficient (attempts do not count yet)");
    }
    if (state == "unavailable") {
        return QObject::tr("not available yet");
    }
    return QString::fromStdString(state);
}

ResultsScreen::ResultsScreen(AppContext& context, qint64 session, const curricula::Task& task,
                             const db::SessionResult& result, QWidget* parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("resultsScreen"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(
        new QLabel(tr("<h2>Results: %1</h2>").arg(QString::fromStdString(task.title).toHtmlEscaped())));

    std::optional<scoring::BenchmarkSet> benchmarks;
    if (const auto stored = context.records.latestBenchmarkSet(task.benchmark)) {
        benchmarks = scoring::BenchmarkSet::fromJson(std::get<2>(*stored));
    }
    const auto met = result.scores.find("benchmark_met");
    auto* summary = new QLabel;
    summary->setObjectName(QStringLiteral("resultSummary"));
    summary->setWordWrap(true);
    if (!benchmarks) {
        summary->setText(
            tr("Session %1 lasted %2 s. No benchmark set \"%3\" is stored yet, so the metrics are "
               "shown without pass or fail; an administrator derives it from expert sessions.")
                .arg(session)
                .arg(result.duration, 0, 'f', 1)
                .arg(QString::fromStdString(task.benchmark)));
    } else {
        const bool passed = met != result.scores.end() && met->second > 0.5;
        const auto composite = result.scores.find("composite");
        summary->setText(tr("Session %1 lasted %2 s. Benchmark \"%3\" %4%5.")
                             .arg(session)
                             .arg(result.duration, 0, 'f', 1)
                             .arg(QString::fromStdString(task.benchmark))
                             .arg(passed ? tr("<b style='color:#1e7d32'>met</b>")
                                         : tr("<b style='color:#b3261e'>not met</b>"))
                             .arg(composite != result.scores.end()
                                      ? tr("; composite score %1 of 100").arg(composite->second, 0, 'f', 0)
                                      : QString()));
    }
    layout->addWidget(summary);

    m_table = new QTableWidget(0, 4);
    m_table->setObjectName(QStringLiteral("metricTable"));
    m_table->setHorizontalHeaderLabels({tr("Metric"), tr("Your value"), tr("Benchmark"), tr("Result")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QStringList improvements;
    for (const scoring::MetricDefinition& definition : scoring::metricDefinitions()) {
        const std::string name(definition.name);
        const auto value = result.metrics.find(name);
        if (value == result.metrics.end()) {
            continue;
        }
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        const QString help =
            QString::fromUtf8(definition.help.data(), static_cast<qsizetype>(definition.help.size()));
        QTableWidgetItem* metric = cell(metricLabel(definition));
        metric->setToolTip(help);
        m_table->setItem(row, 0, metric);
        m_table->setItem(row, 1, cell(valueText(value->second, definition.unit)));
        const bool benchmarked = benchmarks && benchmarks->metrics.contains(name);
        if (!benchmarked) {
            m_table->setItem(row, 2, cell(QStringLiteral("—")));
            m_table->setItem(row, 3, cell(tr("not benchmarked")));
            continue;
        }
        const double limit = benchmarks->limit(name);
        const bool lower = definition.better == scoring::Better::Lower;
        const bool pass =
            !std::isnan(value->second) && (lower ? value->second <= limit : value->second >= limit);
        m_table->setItem(
            row, 2,
            cell((lower ? tr("at most %1") : tr("at least %1")).arg(valueText(limit, definition.unit))));
        QTableWidgetItem* verdict = cell(pass ? tr("pass") : tr("fail"));
        verdict->setForeground(pass ? QColor(30, 125, 50) : QColor(179, 38, 30));
        m_table->setItem(row, 3, verdict);
        if (!pass) {
            improvements << QStringLiteral("<li><b>%1</b> (%2): %3</li>")
                                .arg(metricLabel(definition).toHtmlEscaped(), help.toHtmlEscaped(),
                                     adviceFor(definition.name).toHtmlEscaped());
        }
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    layout->addWidget(m_table, 1);

    auto* improve = new QLabel;
    improve->setObjectName(QStringLiteral("whatToImprove"));
    improve->setWordWrap(true);
    improve->setText(improvements.isEmpty()
                         ? (benchmarks ? tr("<b>What to improve</b>: nothing failed — repeat to confirm it.")
                                       : tr("<b>What to improve</b>: shown once a benchmark set exists."))
                         : tr("<b>What to improve</b><ul>%1</ul>").arg(improvements.join(QString())));
    layout->addWidget(improve);

    auto* progress = new QLabel;
    progress->setObjectName(QStringLiteral("progressionStatus"));
    progress->setWordWrap(true);
    const auto state = result.progress.find(task.id);
    progress->setText(
        tr("<b>Progression</b>: this task is %1.")
            .arg(state != result.progress.end() ? progressionWords(state->second) : tr("not recorded")));
    layout->addWidget(progress);

    auto* buttons = new QHBoxLayout;
    auto* replay = new QPushButton(tr("Replay this session"));
    replay->setObjectName(QStringLiteral("replayButton"));
    connect(replay, &QPushButton::clicked, this, [this, session] { Q_EMIT replayRequested(session); });
    auto* back = new QPushButton(tr("Back to the curriculum"));
    back->setObjectName(QStringLiteral("backToCurriculum"));
    connect(back, &QPushButton::clicked, this, &ResultsScreen::backRequested);
    buttons->addWidget(replay);
    buttons->addStretch();
    buttons->addWidget(back);
    layout->addLayout(buttons);
}

}  // namespace colonosim::app
