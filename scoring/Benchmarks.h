#pragma once
/// \file
/// Benchmarks from expert runs. For each metric with a better direction the
/// set keeps the expert mean and standard deviation over the runs; the
/// acceptable limit is mean + k·SD for lower-is-better metrics and mean - k·SD
/// for higher-is-better ones. The spread used is max(SD, 5% of |mean|), so a
/// perfectly repeatable expert does not give a zero-width band.
///
/// Proficiency of one value, 0-1: 1 inside the limit, falling linearly to 0
/// at three spreads beyond it (model choice: a value 3 spreads past the limit
/// is taken as fully non-proficient).
///
/// A set has a name and a version; a changed set gets a new version and past
/// sessions are re-scored from their stored recordings (db re-scoring).

#include "scoring/SessionMetrics.h"
#include "simcore/params/Parameter.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace colonosim::scoring {

struct MetricBenchmark {
    double mean = 0.0;
    double sd = 0.0;
    int runs = 0;
};

struct BenchmarkSet {
    static constexpr params::ParameterSpec kSpec{"k",
                                                 "1",
                                                 1.0,
                                                 0.0,
                                                 4.0,
                                                 "width of the acceptable band in expert standard deviations",
                                                 "proficiency-based progression: the proficiency level is "
                                                 "the expert mean (clinical-assessment.md); one SD "
                                                 "of slack is a documented choice"};
    std::string name;
    int version = 1;
    double k = kSpec.defaultValue;
    std::map<std::string, MetricBenchmark> metrics;

    /// The acceptable limit of a benchmarked metric.
    [[nodiscard]] double limit(const std::string& metric) const;
    /// 0-1; nullopt when the metric is not benchmarked.
    [[nodiscard]] std::optional<double> proficiency(const std::string& metric, double value) const;
    /// Every benchmarked metric present and within its limit (a metric the
    /// run lacks, e.g. time to cecum when not reached, fails).
    [[nodiscard]] bool met(const MetricValues& values) const;

    [[nodiscard]] std::string toJson() const;
    /// Throws std::invalid_argument naming the field at fault.
    [[nodiscard]] static BenchmarkSet fromJson(const std::string& json);
};

/// Mean and SD (n - 1) of each directed metric over expert runs. A metric
/// absent from some runs is benchmarked over the runs that have it.
[[nodiscard]] BenchmarkSet deriveBenchmarks(const std::string& name, int version, double k,
                                            const std::vector<MetricValues>& expertRuns);

}  // namespace colonosim::scoring
