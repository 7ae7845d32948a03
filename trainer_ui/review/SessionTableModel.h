#pragma once
/// \file
/// Completed sessions as a table: id, date, task, device, duration, composite
/// score and whether the benchmark was met. The session id is the row's
/// Qt::UserRole data.

#include "db/Records.h"

#include <QAbstractTableModel>

#include <vector>

namespace colonosim::app {

class SessionTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;

    void setSessions(std::vector<db::SessionRow> sessions);
    [[nodiscard]] const std::vector<db::SessionRow>& sessions() const { return m_sessions; }

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role = Qt::DisplayRole) const override;

private:
    std::vector<db::SessionRow> m_sessions;
};

}  // namespace colonosim::app
