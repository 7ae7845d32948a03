#pragma once
/// \file
/// The instructor's charts (QtCharts), built from data the records return:
///   metric curve   one metric of one trainee per completed session, with the
///                  benchmark drawn: the acceptable zone (beyond the limit,
///                  expert mean ± k·spread, on the worse side) shaded and the
///                  expert mean dashed
///   CUSUM          S_n of cecal-intubation failures with h1 (unacceptable
///                  rate) and h0 (acceptable rate)
///   LC-CUSUM       with h (competence declared)
/// (scoring/LearningCurve.h has the equations.)

#include "db/Records.h"
#include "scoring/Benchmarks.h"
#include "scoring/LearningCurve.h"

#include <QChart>

#include <optional>
#include <string>
#include <vector>

namespace colonosim::app {

/// Replaces the chart's content. `benchmark` may be absent (no set stored).
void drawMetricCurve(QChart& chart, const std::string& metric, const std::vector<db::CurvePoint>& points,
                     const std::optional<scoring::BenchmarkSet>& benchmark);

void drawCusum(QChart& chart, const scoring::LearningCurve& curve,
               const scoring::CusumParameters& parameters);
void drawLcCusum(QChart& chart, const scoring::LearningCurve& curve,
                 const scoring::CusumParameters& parameters);

}  // namespace colonosim::app
