#include "trainer_ui/review/ComparisonPage.h"
#include "trainer_ui/review/TraineeSessions.h"

#include "scoring/MetricDefinitions.h"
#include "trainer_ui/review/ReadableTrainees.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

namespace colonosim::app {

namespace {

QString label(const db::SessionRow& s)
{
    QString composite = QStringLiteral("not scored");
    if (const auto it = s.scores.find("composite"); it != s.scores.end()) {
        composite = QStringLiteral("composite %1").arg(it->second, 0, 'f', 1);
    }
    return QStringLiteral("%1, session %2 (%3, %4 s, %5)")
        .arg(QString::fromStdString(s.user))
        .arg(s.id)
        .arg(QString::fromStdString(s.task))
        .arg(s.duration, 0, 'f', 1)
        .arg(composite);
}

QString value(const std::map<std::string, double>& values, const std::string& name)
{
    const auto it = values.find(name);
    return it == values.end() ? QStringLiteral("—") : QString::number(it->second, 'g', 3);
}

/// The unit as a person reads it: blank for a count, share or score (unit 1).
QString unitText(std::string_view unit)
{
    return unit == "1" ? QString() : QString::fromUtf8(unit.data(), static_cast<qsizetype>(unit.size()));
}

}  // namespace

ComparisonPage::ComparisonPage(AppContext& context, TraineeSessions& sessions, QWidget* parent)
    : LazyPage(parent), m_context(context), m_cache(sessions), m_first(new QComboBox),
      m_second(new QComboBox), m_model(new QStandardItemModel(this)), m_table(new QTableView),
      m_summary(new QLabel)
{
    m_first->setObjectName(QStringLiteral("compareFirst"));
    m_second->setObjectName(QStringLiteral("compareSecond"));
    m_table->setObjectName(QStringLiteral("comparisonTable"));
    m_summary->setObjectName(QStringLiteral("comparisonSummary"));
    m_summary->setWordWrap(true);
    m_table->setModel(m_model);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* form = new QFormLayout;
    form->addRow(QStringLiteral("Session A:"), m_first);
    form->addRow(QStringLiteral("Session B:"), m_second);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    connect(m_first, &QComboBox::currentIndexChanged, this, &ComparisonPage::redraw);
    connect(m_second, &QComboBox::currentIndexChanged, this, &ComparisonPage::redraw);
}

void ComparisonPage::reload()
{
    m_sessions.clear();
    for (const std::string& trainee : readableTrainees(m_context.records, m_context.actor)) {
        for (const db::SessionRow& s : m_cache.of(trainee)) {
            m_sessions.push_back(s);
        }
    }
    const QSignalBlocker blockFirst(m_first);
    const QSignalBlocker blockSecond(m_second);
    m_first->clear();
    m_second->clear();
    for (const db::SessionRow& s : m_sessions) {
        m_first->addItem(label(s), s.id);
        m_second->addItem(label(s), s.id);
    }
    if (m_sessions.size() > 1) {
        m_second->setCurrentIndex(1);
    }
    redraw();
}

bool ComparisonPage::compare(qint64 first, qint64 second)
{
    const int a = m_first->findData(first);
    const int b = m_second->findData(second);
    if (a < 0 || b < 0) {
        return false;
    }
    m_first->setCurrentIndex(a);
    m_second->setCurrentIndex(b);
    return true;
}

void ComparisonPage::redraw()
{
    m_model->clear();
    m_model->setHorizontalHeaderLabels({QStringLiteral("Metric"), QStringLiteral("Unit"), QStringLiteral("A"),
                                        QStringLiteral("B"), QStringLiteral("Better")});
    const int a = m_first->currentIndex();
    const int b = m_second->currentIndex();
    if (a < 0 || b < 0) {
        m_summary->setText(QStringLiteral("There are no completed sessions to compare yet."));
        return;
    }
    const db::SessionRow& first = m_sessions[static_cast<size_t>(a)];
    const db::SessionRow& second = m_sessions[static_cast<size_t>(b)];
    int winsA = 0;
    int winsB = 0;
    const QColor better(200, 235, 205);
    for (const scoring::MetricDefinition& d : scoring::metricDefinitions()) {
        const std::string name(d.name);
        QList<QStandardItem*> row{
            new QStandardItem(QString::fromUtf8(d.label.data(), static_cast<qsizetype>(d.label.size()))),
            new QStandardItem(unitText(d.unit)), new QStandardItem(value(first.metrics, name)),
            new QStandardItem(value(second.metrics, name)), new QStandardItem};
        row[0]->setToolTip(QString::fromStdString(name) + QStringLiteral(": ") +
                           QString::fromUtf8(d.help.data(), static_cast<qsizetype>(d.help.size())));
        const auto x = first.metrics.find(name);
        const auto y = second.metrics.find(name);
        QString verdict;
        if (d.better == scoring::Better::Neither) {
            verdict = QStringLiteral("no better direction");
        } else if (x == first.metrics.end() || y == second.metrics.end()) {
            verdict = QStringLiteral("not measured in both");
        } else if (row[2]->text() == row[3]->text()) {
            // Equal to the 3 significant digits shown: a difference no one can read is no verdict.
            verdict = QStringLiteral("equal");
        } else {
            const bool aBetter =
                d.better == scoring::Better::Lower ? x->second < y->second : x->second > y->second;
            verdict = aBetter ? QStringLiteral("A") : QStringLiteral("B");
            (aBetter ? winsA : winsB) += 1;
            row[aBetter ? 2 : 3]->setBackground(better);
        }
        row[4]->setText(verdict);
        m_model->appendRow(row);
    }
    m_table->resizeColumnsToContents();
    m_summary->setText(QStringLiteral("A: %1\nB: %2\nA is better in %3 metric(s), B in %4; shaded: the "
                                      "better value.")
                           .arg(label(first), label(second))
                           .arg(winsA)
                           .arg(winsB));
}

}  // namespace colonosim::app
