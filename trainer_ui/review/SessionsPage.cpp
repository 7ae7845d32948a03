#include "trainer_ui/review/SessionsPage.h"
#include "trainer_ui/review/TraineeSessions.h"

#include "trainer_ui/review/ReadableTrainees.h"
#include "trainer_ui/review/SessionTableModel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace colonosim::app {

SessionsPage::SessionsPage(AppContext& context, TraineeSessions& sessions, QWidget* parent)
    : LazyPage(parent), m_context(context), m_cache(sessions), m_trainee(new QComboBox),
      m_model(new SessionTableModel(this)), m_table(new QTableView),
      m_replay(new QPushButton(QStringLiteral("Replay"))), m_status(new QLabel)
{
    m_trainee->setObjectName(QStringLiteral("sessionTrainee"));
    m_table->setObjectName(QStringLiteral("sessionTable"));
    m_replay->setObjectName(QStringLiteral("replayButton"));
    m_status->setWordWrap(true);
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->horizontalHeader()->setResizeContentsPrecision(100);  // column widths from 100 rows, not 10,000
    m_replay->setEnabled(false);
    m_replay->setToolTip(QStringLiteral("Replays the chosen session from its stored input trace"));
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(QStringLiteral("Trainee:")));
    top->addWidget(m_trainee, 1);
    top->addStretch(2);
    top->addWidget(m_replay);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);
    connect(m_trainee, &QComboBox::currentIndexChanged, this, &SessionsPage::load);
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            [this] { m_replay->setEnabled(chosenSession() > 0); });
    connect(m_table, &QTableView::doubleClicked, this, [this] {
        if (chosenSession() > 0) {
            Q_EMIT replayRequested(chosenSession());
        }
    });
    connect(m_replay, &QPushButton::clicked, this, [this] {
        if (const qint64 session = chosenSession(); session > 0) {
            Q_EMIT replayRequested(session);
        }
    });
}

void SessionsPage::reload()
{
    const QString current = m_trainee->currentText();
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
    load();
}

void SessionsPage::load()
{
    try {
        const std::string trainee = m_trainee->currentText().toStdString();
        m_model->setSessions(trainee.empty() ? std::vector<db::SessionRow>{} : m_cache.of(trainee));
        m_table->resizeColumnsToContents();
        m_status->setText(trainee.empty() ? QStringLiteral("No trainee to show.")
                                          : QStringLiteral("%1 completed session(s). Choose one and press "
                                                           "Replay (or double-click it).")
                                                .arg(m_model->rowCount()));
    } catch (const std::exception& e) {
        m_model->setSessions({});
        m_status->setText(QString::fromStdString(e.what()));
    }
    m_replay->setEnabled(false);
}

qint64 SessionsPage::chosenSession() const
{
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    return rows.isEmpty() ? 0 : rows.front().data(Qt::UserRole).toLongLong();
}

}  // namespace colonosim::app
