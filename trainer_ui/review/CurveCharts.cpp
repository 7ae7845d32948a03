#include "trainer_ui/review/CurveCharts.h"

#include "scoring/MetricDefinitions.h"

#include <QAreaSeries>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace colonosim::app {

namespace {

const QColor kTrainee(20, 80, 180);
const QColor kLimit(200, 40, 40);
const QColor kAcceptable(60, 160, 80, 60);

struct Axes {
    QValueAxis* x;
    QValueAxis* y;
};

Axes resetChart(QChart& chart, const QString& title, const QString& yTitle, int sessions)
{
    chart.removeAllSeries();
    for (QAbstractAxis* axis : chart.axes()) {
        chart.removeAxis(axis);
        delete axis;
    }
    chart.setTitle(title);
    chart.legend()->setAlignment(Qt::AlignBottom);
    auto* x = new QValueAxis;
    x->setTitleText(QStringLiteral("session"));
    x->setLabelFormat(QStringLiteral("%d"));
    x->setRange(0.5, std::max(sessions, 1) + 0.5);
    x->setTickType(QValueAxis::TicksDynamic);
    x->setTickAnchor(1.0);
    x->setTickInterval(std::max(1.0, std::ceil(sessions / 10.0)));
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    chart.addAxis(x, Qt::AlignBottom);
    chart.addAxis(y, Qt::AlignLeft);
    return {x, y};
}

void attach(QChart& chart, QAbstractSeries* series, const Axes& axes)
{
    chart.addSeries(series);
    series->attachAxis(axes.x);
    series->attachAxis(axes.y);
}

QLineSeries* horizontal(const QString& name, double y, double x0, double x1, const QColor& colour,
                        Qt::PenStyle style)
{
    auto* line = new QLineSeries;
    line->setName(name);
    line->append(x0, y);
    line->append(x1, y);
    QPen pen(colour, 2.0, style);
    line->setPen(pen);
    return line;
}

/// The trainee's values as a line, with a point per session while they can be told apart.
void traineeSeries(QChart& chart, const Axes& axes, const QString& name, const std::vector<double>& values)
{
    constexpr size_t kMostDots = 200;
    auto* line = new QLineSeries;
    line->setName(name);
    line->setPen(QPen(kTrainee, 2.5));
    auto* dots = new QScatterSeries;
    dots->setColor(kTrainee);
    dots->setBorderColor(kTrainee);
    dots->setMarkerSize(9.0);
    QList<QPointF> points;
    points.reserve(static_cast<qsizetype>(values.size()));
    for (size_t k = 0; k < values.size(); ++k) {
        points.append(QPointF(static_cast<double>(k + 1), values[k]));
    }
    line->replace(points);
    attach(chart, line, axes);
    if (values.size() <= kMostDots) {
        dots->replace(points);
        attach(chart, dots, axes);
        chart.legend()->markers(dots).front()->setVisible(false);
    } else {
        delete dots;
    }
}

void fitY(QValueAxis& y, std::vector<double> values)
{
    if (values.empty()) {
        y.setRange(0.0, 1.0);
        return;
    }
    double lo = *std::min_element(values.begin(), values.end());
    double hi = *std::max_element(values.begin(), values.end());
    const double pad = std::max(0.08 * (hi - lo), 1e-6 + 0.05 * std::abs(hi));
    y.setRange(lo - pad, hi + pad);
    y.applyNiceNumbers();
}

}  // namespace

void drawMetricCurve(QChart& chart, const std::string& metric, const std::vector<db::CurvePoint>& points,
                     const std::optional<scoring::BenchmarkSet>& benchmark)
{
    const scoring::MetricDefinition* definition = scoring::findMetric(metric);
    const QString unit = definition ? QString::fromUtf8(definition->unit.data(),
                                                        static_cast<qsizetype>(definition->unit.size()))
                                    : QString();
    const int n = static_cast<int>(points.size());
    const Axes axes = resetChart(chart, QString::fromStdString(metric),
                                 unit.isEmpty() || unit == QStringLiteral("1")
                                     ? QString::fromStdString(metric)
                                     : QStringLiteral("%1 [%2]").arg(QString::fromStdString(metric), unit),
                                 n);
    std::vector<double> values;
    for (const db::CurvePoint& p : points) {
        values.push_back(p.value);
    }
    std::vector<double> extent = values;
    const bool benchmarked = benchmark && benchmark->metrics.contains(metric) && definition &&
                             definition->better != scoring::Better::Neither;
    double limit = 0.0;
    double mean = 0.0;
    if (benchmarked) {
        limit = benchmark->limit(metric);
        mean = benchmark->metrics.at(metric).mean;
        extent.push_back(limit);
        extent.push_back(mean);
    }
    fitY(*axes.y, extent);
    const double x0 = axes.x->min();
    const double x1 = axes.x->max();
    if (benchmarked) {
        // The acceptable zone: from the limit to the edge of the chart on the better side.
        const double edge = definition->better == scoring::Better::Lower ? axes.y->min() : axes.y->max();
        auto* upper = new QLineSeries;
        auto* lower = new QLineSeries;
        upper->append(x0, std::max(limit, edge));
        upper->append(x1, std::max(limit, edge));
        lower->append(x0, std::min(limit, edge));
        lower->append(x1, std::min(limit, edge));
        auto* band = new QAreaSeries(upper, lower);
        band->setName(QStringLiteral("acceptable (benchmark %1 v%2)")
                          .arg(QString::fromStdString(benchmark->name))
                          .arg(benchmark->version));
        band->setColor(kAcceptable);
        band->setBorderColor(Qt::transparent);
        attach(chart, band, axes);
        attach(chart, horizontal(QStringLiteral("limit"), limit, x0, x1, kLimit, Qt::SolidLine), axes);
        attach(chart,
               horizontal(QStringLiteral("expert mean"), mean, x0, x1, QColor(60, 60, 60), Qt::DashLine),
               axes);
    }
    traineeSeries(chart, axes, QStringLiteral("trainee"), values);
}

void drawCusum(QChart& chart, const scoring::LearningCurve& curve, const scoring::CusumParameters& parameters)
{
    const int n = static_cast<int>(curve.cusum.size());
    const Axes axes = resetChart(chart,
                                 QStringLiteral("CUSUM of cecal intubation failures (p0 %1, p1 %2)")
                                     .arg(parameters.acceptable)
                                     .arg(parameters.unacceptable),
                                 QStringLiteral("S_n"), n);
    std::vector<double> extent = curve.cusum;
    extent.push_back(parameters.upperLimit());
    extent.push_back(parameters.lowerLimit());
    extent.push_back(0.0);
    fitY(*axes.y, extent);
    attach(chart,
           horizontal(QStringLiteral("h1: unacceptable"), parameters.upperLimit(), axes.x->min(),
                      axes.x->max(), kLimit, Qt::DashLine),
           axes);
    attach(chart,
           horizontal(QStringLiteral("h0: acceptable"), parameters.lowerLimit(), axes.x->min(), axes.x->max(),
                      QColor(40, 140, 60), Qt::DashLine),
           axes);
    traineeSeries(chart, axes, QStringLiteral("CUSUM"), curve.cusum);
}

void drawLcCusum(QChart& chart, const scoring::LearningCurve& curve,
                 const scoring::CusumParameters& parameters)
{
    const int n = static_cast<int>(curve.lcCusum.size());
    const Axes axes =
        resetChart(chart, QStringLiteral("LC-CUSUM of cecal intubation"), QStringLiteral("S_n"), n);
    std::vector<double> extent = curve.lcCusum;
    extent.push_back(parameters.lcLimit());
    extent.push_back(0.0);
    fitY(*axes.y, extent);
    attach(chart,
           horizontal(QStringLiteral("h: competent"), parameters.lcLimit(), axes.x->min(), axes.x->max(),
                      QColor(40, 140, 60), Qt::DashLine),
           axes);
    traineeSeries(chart, axes, QStringLiteral("LC-CUSUM"), curve.lcCusum);
}

}  // namespace colonosim::app
