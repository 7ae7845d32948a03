#include "trainer_ui/review/SessionTableModel.h"

#include <QDateTime>

namespace colonosim::app {

namespace {
enum Column { Id, Started, Task, Device, Duration, Composite, Benchmark, NumColumns };
}

void SessionTableModel::setSessions(std::vector<db::SessionRow> sessions)
{
    beginResetModel();
    m_sessions = std::move(sessions);
    endResetModel();
}

int SessionTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_sessions.size());
}

int SessionTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : NumColumns;
}

QVariant SessionTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount()) {
        return {};
    }
    const db::SessionRow& s = m_sessions[static_cast<size_t>(index.row())];
    if (role == Qt::UserRole) {
        return s.id;
    }
    if (role == Qt::TextAlignmentRole && (index.column() == Duration || index.column() == Composite)) {
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    }
    if (role != Qt::DisplayRole) {
        return {};
    }
    switch (index.column()) {
    case Id: return s.id;
    case Started:
        return QDateTime::fromString(QString::fromStdString(s.startedAt), Qt::ISODateWithMs)
            .toLocalTime()
            .toString(QStringLiteral("yyyy-MM-dd HH:mm"));
    case Task: return QString::fromStdString(s.task);
    case Device: return QString::fromStdString(s.device);
    case Duration: return QStringLiteral("%1 s").arg(s.duration, 0, 'f', 1);
    case Composite:
        if (const auto it = s.scores.find("composite"); it != s.scores.end()) {
            return QString::number(it->second, 'f', 1);
        }
        return QStringLiteral("not scored");
    case Benchmark:
        if (const auto it = s.scores.find("benchmark_met"); it != s.scores.end()) {
            return it->second > 0.5 ? QStringLiteral("met") : QStringLiteral("not met");
        }
        return QStringLiteral("no benchmark");
    default: return {};
    }
}

QVariant SessionTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) {
        return {};
    }
    static const char* names[] = {"Session",  "Started",   "Task",     "Device",
                                  "Duration", "Composite", "Benchmark"};
    return section >= 0 && section < NumColumns ? QString::fromLatin1(names[section]) : QVariant();
}

}  // namespace colonosim::app
