#include "trainer_ui/review/TraineesPage.h"
#include "trainer_ui/review/TraineeSessions.h"

#include "db/CertificationRules.h"
#include "db/Cohorts.h"
#include "trainer_ui/reports/ProgressReport.h"

#include <QHeaderView>
#include <QLabel>
#include <QStandardItemModel>
#include <QTreeView>
#include <QVBoxLayout>

namespace colonosim::app {

TraineesPage::TraineesPage(AppContext& context, TraineeSessions& sessions, QWidget* parent)
    : LazyPage(parent), m_context(context), m_cache(sessions), m_model(new QStandardItemModel(this)),
      m_tree(new QTreeView), m_summary(new QLabel)
{
    m_tree->setObjectName(QStringLiteral("traineeTree"));
    m_tree->setModel(m_model);
    m_tree->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tree->setAlternatingRowColors(true);
    m_summary->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    connect(m_tree, &QTreeView::doubleClicked, this, [this](const QModelIndex& index) {
        const QModelIndex name = index.siblingAtColumn(0);
        if (name.parent().isValid()) {
            Q_EMIT traineeChosen(name.data().toString());
        }
    });
}

void TraineesPage::reload()
{
    m_model->clear();
    m_model->setHorizontalHeaderLabels({QStringLiteral("Cohort / trainee"), QStringLiteral("Sessions"),
                                        QStringLiteral("Last composite"), QStringLiteral("Cecal intubation"),
                                        QStringLiteral("Certification rules met")});
    const std::vector<db::CohortRow> cohorts = db::readableCohorts(m_context.database, m_context.actor);
    // The rules every trainee is judged by; when the active set cannot be read,
    // the certification column says why instead of a count.
    db::ActiveRuleSet ruleSet{{0, {}, 0, {}, {}, false}, {}};
    QString ruleSetProblem;
    try {
        ruleSet = db::CertificationRules(m_context.database).active(m_context.actor);
    } catch (const db::DatabaseError& e) {
        ruleSetProblem = QString::fromStdString(e.what());
    }
    int trainees = 0;
    for (const db::CohortRow& cohort : cohorts) {
        auto* group = new QStandardItem(QString::fromStdString(cohort.name));
        QFont bold = group->font();
        bold.setBold(true);
        group->setFont(bold);
        QList<QStandardItem*> groupRow{group};
        for (int c = 1; c < 5; ++c) {
            groupRow.append(new QStandardItem);
        }
        groupRow[1]->setText(QStringLiteral("%1 trainee(s)").arg(cohort.members.size()));
        for (const std::string& member : cohort.members) {
            QList<QStandardItem*> row{new QStandardItem(QString::fromStdString(member))};
            try {
                const auto& sessions = m_cache.of(member);
                const nlohmann::json progress = reports::progressReport(sessions, member, ruleSet);
                row.append(new QStandardItem(QString::number(sessions.size())));
                QString composite = QStringLiteral("not scored");
                if (!sessions.empty() && sessions.back().scores.contains("composite")) {
                    composite = QString::number(sessions.back().scores.at("composite"), 'f', 1);
                }
                row.append(new QStandardItem(composite));
                const auto& lc = progress["learning_curve"];
                row.append(new QStandardItem(
                    lc["competent_at"].get<int>() > 0
                        ? QStringLiteral("competent at session %1").arg(lc["competent_at"].get<int>())
                        : (lc["unacceptable_at"].get<int>() > 0
                               ? QStringLiteral("failure rate unacceptable since session %1")
                                     .arg(lc["unacceptable_at"].get<int>())
                               : QStringLiteral("not yet decided"))));
                int met = 0;
                int rules = 0;
                for (const auto& r : progress["certification"]) {
                    ++rules;
                    met += r["met"].get<bool>() ? 1 : 0;
                }
                row.append(new QStandardItem(ruleSetProblem.isEmpty()
                                                 ? QStringLiteral("%1 of %2").arg(met).arg(rules)
                                                 : ruleSetProblem));
            } catch (const db::AccessDenied& e) {
                row.append(new QStandardItem(QString::fromStdString(e.what())));
            }
            group->appendRow(row);
            ++trainees;
        }
        m_model->appendRow(groupRow);
    }
    m_tree->expandAll();
    for (int c = 0; c < m_model->columnCount(); ++c) {
        m_tree->resizeColumnToContents(c);
    }
    m_summary->setText(
        cohorts.empty() ? QStringLiteral("You are not assigned to any cohort yet: an administrator assigns "
                                         "instructors to cohorts.")
                        : QStringLiteral("%1 cohort(s), %2 trainee(s). Double-click a trainee to see "
                                         "their learning curves.")
                              .arg(cohorts.size())
                              .arg(trainees));
}

}  // namespace colonosim::app
