#pragma once
/// \file
/// Two completed sessions side by side: every metric of both, and which is
/// better by the metric's declared direction (scoring/MetricDefinitions.h);
/// metrics without a better direction are shown without a verdict.

#include "trainer_ui/app/AppContext.h"

#include "trainer_ui/review/LazyPage.h"

#include <vector>

class QComboBox;
class QLabel;
class QStandardItemModel;
class QTableView;

namespace colonosim::app {

class TraineeSessions;

class ComparisonPage : public LazyPage {
    Q_OBJECT
public:
    ComparisonPage(AppContext& context, TraineeSessions& sessions, QWidget* parent = nullptr);
    /// Chooses two sessions by id (false when either is not listed).
    bool compare(qint64 first, qint64 second);

protected:
    void reload() override;

private:
    void redraw();

    AppContext& m_context;
    TraineeSessions& m_cache;
    std::vector<db::SessionRow> m_sessions;
    QComboBox* m_first;
    QComboBox* m_second;
    QStandardItemModel* m_model;
    QTableView* m_table;
    QLabel* m_summary;
};

}  // namespace colonosim::app
