#include "trainer_ui/review/CurvesPage.h"
#include "trainer_ui/review/TraineeSessions.h"

#include "curricula/Curriculum.h"
#include "scoring/MetricDefinitions.h"
#include "trainer_ui/review/CurveCharts.h"
#include "trainer_ui/review/ReadableTrainees.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>

namespace colonosim::app {

namespace {

QChartView* chartView(const QString& name)
{
    auto* view = new QChartView(new QChart);
    view->setObjectName(name);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(360, 260);
    return view;
}

/// The benchmark set of `task` (its latest version), when one is stored.
std::optional<scoring::BenchmarkSet> benchmarkOf(db::Records& records, const std::string& task)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    const curricula::Task* entry = curriculum.value->find(task);
    if (!entry) {
        return std::nullopt;
    }
    const auto stored = records.latestBenchmarkSet(entry->benchmark);
    if (!stored) {
        return std::nullopt;
    }
    return scoring::BenchmarkSet::fromJson(std::get<2>(*stored));
}

}  // namespace

CurvesPage::CurvesPage(AppContext& context, TraineeSessions& sessions, QWidget* parent)
    : LazyPage(parent), m_context(context), m_cache(sessions), m_trainee(new QComboBox),
      m_metric(new QComboBox), m_caption(new QLabel), m_metricView(chartView(QStringLiteral("metricChart"))),
      m_cusumView(chartView(QStringLiteral("cusumChart"))),
      m_lcCusumView(chartView(QStringLiteral("lcCusumChart")))
{
    m_trainee->setObjectName(QStringLiteral("curveTrainee"));
    m_metric->setObjectName(QStringLiteral("curveMetric"));
    m_caption->setObjectName(QStringLiteral("curveCaption"));
    m_caption->setWordWrap(true);
    for (const scoring::MetricDefinition& d : scoring::metricDefinitions()) {
        const QString name = QString::fromUtf8(d.name.data(), static_cast<qsizetype>(d.name.size()));
        m_metric->addItem(QString::fromUtf8(d.label.data(), static_cast<qsizetype>(d.label.size())), name);
        m_metric->setItemData(m_metric->count() - 1,
                              QString::fromUtf8(d.help.data(), static_cast<qsizetype>(d.help.size())),
                              Qt::ToolTipRole);
    }
    m_metric->setCurrentIndex(std::max(0, m_metric->findData(QStringLiteral("max_insertion"))));
    auto* choices = new QHBoxLayout;
    choices->addWidget(new QLabel(QStringLiteral("Trainee:")));
    choices->addWidget(m_trainee, 1);
    choices->addSpacing(16);
    choices->addWidget(new QLabel(QStringLiteral("Metric:")));
    choices->addWidget(m_metric, 2);
    auto* grid = new QGridLayout;
    grid->addWidget(m_metricView, 0, 0, 1, 2);
    grid->addWidget(m_cusumView, 1, 0);
    grid->addWidget(m_lcCusumView, 1, 1);
    grid->setRowStretch(0, 3);
    grid->setRowStretch(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(choices);
    layout->addWidget(m_caption);
    layout->addLayout(grid, 1);
    connect(m_trainee, &QComboBox::currentIndexChanged, this, &CurvesPage::redraw);
    connect(m_metric, &QComboBox::currentIndexChanged, this, &CurvesPage::redraw);
}

void CurvesPage::reload()
{
    const QString current = m_wanted.isEmpty() ? m_trainee->currentText() : m_wanted;
    m_wanted.clear();
    {
        const QSignalBlocker block(m_trainee);
        m_trainee->clear();
        for (const std::string& name : readableTrainees(m_context.records, m_context.actor)) {
            m_trainee->addItem(QString::fromStdString(name));
        }
        if (const int k = m_trainee->findText(current); k >= 0) {
            m_trainee->setCurrentIndex(k);
        }
    }
    redraw();
}

void CurvesPage::showTrainee(const QString& trainee)
{
    if (const int k = m_trainee->findText(trainee); k >= 0) {
        m_trainee->setCurrentIndex(k);
    } else {
        m_wanted = trainee;
    }
}

void CurvesPage::redraw()
{
    const std::string trainee = m_trainee->currentText().toStdString();
    const std::string metric = m_metric->currentData().toString().toStdString();
    if (trainee.empty()) {
        m_caption->setText(QStringLiteral("No trainee to show: none of your cohorts has a student yet."));
        return;
    }
    try {
        const std::vector<db::SessionRow>& sessions = m_cache.of(trainee);
        std::vector<db::CurvePoint> points;
        for (const db::SessionRow& s : sessions) {
            if (const auto it = s.metrics.find(metric); it != s.metrics.end()) {
                points.push_back({s.id, it->second});
            }
        }
        const std::string task = sessions.empty() ? std::string() : sessions.back().task;
        const std::optional<scoring::BenchmarkSet> benchmark =
            task.empty() ? std::nullopt : benchmarkOf(m_context.records, task);
        drawMetricCurve(*m_metricView->chart(), metric, points, benchmark);
        std::vector<bool> failures;
        for (const db::SessionRow& s : sessions) {
            const auto cecum = s.metrics.find("cecal_intubation");
            failures.push_back(cecum == s.metrics.end() || cecum->second < 0.5);
        }
        const scoring::CusumParameters parameters;
        const scoring::LearningCurve curve = scoring::learningCurve(failures, parameters);
        drawCusum(*m_cusumView->chart(), curve, parameters);
        drawLcCusum(*m_lcCusumView->chart(), curve, parameters);
        QString text = QStringLiteral("%1: %2 completed session(s), %3 with %4.")
                           .arg(QString::fromStdString(trainee))
                           .arg(sessions.size())
                           .arg(points.size())
                           .arg(QString::fromStdString(metric));
        if (sessions.empty()) {
            text += QStringLiteral(" The charts fill as sessions are completed.");
        } else if (!benchmark) {
            text += QStringLiteral(" No benchmark set is stored for task %1 yet, so no band is drawn.")
                        .arg(QString::fromStdString(task));
        } else if (!benchmark->metrics.contains(metric)) {
            text += QStringLiteral(" The benchmark of task %1 does not rate this metric.")
                        .arg(QString::fromStdString(task));
        }
        text += curve.competentAt > 0
                    ? QStringLiteral(" LC-CUSUM: competent at session %1.").arg(curve.competentAt)
                    : QStringLiteral(" LC-CUSUM: competence not yet signalled.");
        m_caption->setText(text);
    } catch (const std::exception& e) {
        m_caption->setText(QString::fromStdString(e.what()));
    }
}

}  // namespace colonosim::app
