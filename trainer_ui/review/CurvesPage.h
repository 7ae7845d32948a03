#pragma once
/// \file
/// One trainee's learning curves: a chosen metric per completed session
/// against the benchmark of the trainee's latest task, and the CUSUM and
/// LC-CUSUM charts of cecal intubation with their decision limits.

#include "trainer_ui/app/AppContext.h"

#include "trainer_ui/review/LazyPage.h"

class QComboBox;
class QLabel;
class QChartView;
class QChart;

namespace colonosim::app {

class TraineeSessions;

class CurvesPage : public LazyPage {
    Q_OBJECT
public:
    CurvesPage(AppContext& context, TraineeSessions& sessions, QWidget* parent = nullptr);
    void showTrainee(const QString& trainee);

protected:
    void reload() override;

private:
    void redraw();

    AppContext& m_context;
    TraineeSessions& m_cache;
    QComboBox* m_trainee;
    QComboBox* m_metric;
    QLabel* m_caption;
    QChartView* m_metricView;
    QChartView* m_cusumView;
    QChartView* m_lcCusumView;
    QString m_wanted;  ///< the trainee to show once the page has loaded
};

}  // namespace colonosim::app
