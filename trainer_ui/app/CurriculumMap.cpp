#include "trainer_ui/app/CurriculumMap.h"

#include "curricula/Progression.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <stdexcept>

namespace colonosim::app {

namespace {
constexpr int kTaskRole = Qt::UserRole + 1;

QString stateText(const std::string& state)
{
    if (state == "unlocked") {
        return QObject::tr("open");
    }
    if (state == "proficient") {
        return QObject::tr("proficient ✓");
    }
    if (state == "unavailable") {
        return QObject::tr("not available yet");
    }
    return QObject::tr("locked");
}

QColor stateColour(const std::string& state)
{
    if (state == "unlocked") {
        return {21, 101, 192};
    }
    if (state == "proficient") {
        return {30, 125, 50};
    }
    return {110, 110, 110};
}
}  // namespace

curricula::Curriculum loadCurriculum(AppContext& context)
{
    const std::optional<std::string> stored = context.records.curriculum(context.actor, cli::kCoreCurriculum);
    const std::string& xml = stored ? *stored : curricula::coreCurriculumXml();
    curricula::CurriculumRead read =
        curricula::parseCurriculum(xml, std::string(cli::kCoreCurriculum) + ".xml");
    if (!read.ok()) {
        std::string message = "the stored curriculum cannot be read:";
        for (const std::string& error : read.errors) {
            message += "\n" + error;
        }
        throw std::runtime_error(message);
    }
    return std::move(*read.value);
}

CurriculumMap::CurriculumMap(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context), m_curriculum(loadCurriculum(context))
{
    setObjectName(QStringLiteral("studentHome"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(
        new QLabel(tr("<h2>Your curriculum: %1</h2>").arg(QString::fromStdString(m_curriculum.name))));
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("curriculumSummary"));
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    m_tree = new QTreeWidget;
    m_tree->setObjectName(QStringLiteral("curriculumMap"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Module and task"), tr("State"), tr("Attempts")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->setRootIsDecorated(true);
    connect(m_tree, &QTreeWidget::itemDoubleClicked, this, &CurriculumMap::openSelected);
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this, &CurriculumMap::selectionChanged);
    m_tree->setStyleSheet(QStringLiteral("QTreeWidget::item { padding: 4px; }"));
    layout->addWidget(m_tree, 1);
    m_preview = new QLabel;
    m_preview->setObjectName(QStringLiteral("taskPreview"));
    m_preview->setWordWrap(true);
    m_preview->setMinimumHeight(60);
    m_preview->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(m_preview);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch();
    m_open = new QPushButton(tr("Open the task brief"));
    m_open->setObjectName(QStringLiteral("openBrief"));
    connect(m_open, &QPushButton::clicked, this, &CurriculumMap::openSelected);
    buttons->addWidget(m_open);
    layout->addLayout(buttons);
    refresh();
}

std::string CurriculumMap::stateOf(const std::string& task) const
{
    const auto it = m_states.find(task);
    return it != m_states.end() ? it->second : std::string("locked");
}

void CurriculumMap::refresh()
{
    m_states.clear();
    for (const auto& [task, state] : curricula::progression(m_curriculum, {})) {
        m_states[task] = curricula::stateName(state);
    }
    for (const auto& [task, state] :
         m_context.records.progress(m_context.actor, m_context.actor.name, m_curriculum.name)) {
        m_states[task] = state;
    }
    std::map<std::string, int> attempts;
    for (const db::SessionRow& row : m_context.records.sessions(m_context.actor, m_context.actor.name)) {
        ++attempts[row.task];
    }
    m_next.reset();
    for (const curricula::Task& task : m_curriculum.tasks) {
        if (stateOf(task.id) == "unlocked" && task.available) {
            m_next = task.id;
            break;
        }
    }

    m_tree->clear();
    int proficient = 0;
    QTreeWidgetItem* nextItem = nullptr;
    for (const curricula::Module& module : m_curriculum.modules) {
        auto* moduleItem = new QTreeWidgetItem(m_tree, {QString::fromStdString(module.title)});
        QFont bold = moduleItem->font(0);
        bold.setBold(true);
        moduleItem->setFont(0, bold);
        moduleItem->setFlags(Qt::ItemIsEnabled);
        for (const curricula::Task& task : m_curriculum.tasks) {
            if (task.module != module.id) {
                continue;
            }
            const std::string state = stateOf(task.id);
            proficient += state == "proficient" ? 1 : 0;
            QString title = QString::fromStdString(task.title);
            if (m_next == task.id) {
                title += tr("  ← next");
            }
            auto* item = new QTreeWidgetItem(moduleItem,
                                             {title, stateText(state), QString::number(attempts[task.id])});
            item->setData(0, kTaskRole, QString::fromStdString(task.id));
            item->setForeground(1, stateColour(state));
            item->setToolTip(
                0, QString::fromStdString(task.available ? task.instructions : task.unavailableReason));
            if (m_next == task.id) {
                QFont font = item->font(0);
                font.setBold(true);
                item->setFont(0, font);
                nextItem = item;
            }
        }
    }
    m_tree->expandAll();
    m_tree->resizeColumnToContents(1);
    m_tree->resizeColumnToContents(2);
    m_summary->setText(
        m_next ? tr("%1 of %2 tasks proficient. Next: <b>%3</b>. Select an open task and open its brief.")
                     .arg(proficient)
                     .arg(m_curriculum.tasks.size())
                     .arg(QString::fromStdString(m_curriculum.find(*m_next)->title).toHtmlEscaped())
               : tr("%1 of %2 tasks proficient. No task is open to you now.")
                     .arg(proficient)
                     .arg(m_curriculum.tasks.size()));
    if (nextItem != nullptr) {
        m_tree->setCurrentItem(nextItem);
    }
    selectionChanged();
}

void CurriculumMap::selectionChanged()
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    const std::string id =
        item != nullptr ? item->data(0, kTaskRole).toString().toStdString() : std::string();
    const curricula::Task* task = id.empty() ? nullptr : m_curriculum.find(id);
    const std::string state = task != nullptr ? stateOf(id) : std::string();
    m_open->setEnabled(task != nullptr && task->available && (state == "unlocked" || state == "proficient"));
    if (task == nullptr) {
        m_preview->setText(tr("Select a task to see what it asks."));
        return;
    }
    QString why;
    if (!task->available) {
        why =
            tr("Not available yet: %1.").arg(QString::fromStdString(task->unavailableReason).toHtmlEscaped());
    } else if (state == "locked") {
        QStringList needed;
        for (const std::string& prerequisite : task->prerequisites) {
            if (const curricula::Task* before = m_curriculum.find(prerequisite)) {
                needed << QString::fromStdString(before->title).toHtmlEscaped();
            }
        }
        why = tr("Locked until you are proficient in: %1.").arg(needed.join(tr(", ")));
    }
    m_preview->setText(tr("<b>%1</b>: %2 %3")
                           .arg(QString::fromStdString(task->title).toHtmlEscaped(),
                                QString::fromStdString(task->instructions).toHtmlEscaped(), why));
}

void CurriculumMap::openSelected()
{
    if (!m_open->isEnabled() || m_tree->currentItem() == nullptr) {
        return;
    }
    Q_EMIT briefRequested(m_tree->currentItem()->data(0, kTaskRole).toString());
}

}  // namespace colonosim::app
