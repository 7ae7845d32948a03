#pragma once
/// \file
/// One trainee's learning curves: a chosen metric per completed session
/// against the benchmark of the trainee's latest task, and the CUSUM and
/// LC-CUSUM charts of cecal intubation with their decision limits.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QChartView;
class QChart;

namespace colonosim::app {

class CurvesPage : public QWidget {
    Q_OBJECT
public:
    explicit CurvesPage(AppContext& context, QWidget* parent = nullptr);
    void refresh();
    void showTrainee(const QString& trainee);

private:
    void redraw();

    AppContext& m_context;
    QComboBox* m_trainee;
    QComboBox* m_metric;
    QLabel* m_caption;
    QChartView* m_metricView;
    QChartView* m_cusumView;
    QChartView* m_lcCusumView;
};

}  // namespace colonosim::app
