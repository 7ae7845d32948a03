#pragma once
/// \file
/// Domain scores: the metrics mapped to the five GAGES-C domains (1-5) and to
/// JAG DOPS procedure items (1-4, the supervision scale). A domain's score is
/// 1 + (top - 1) x the mean proficiency (Benchmarks.h) of its metrics that
/// the benchmark set covers; a domain with none is not scored (absent).
///
/// Mapping (domain or item: metrics)
///   GAGES-C scope navigation:            max_insertion, insertion_efficiency, tip_path_length, time_to_cecum
///   GAGES-C strategies for advancement:  loop_count, looped_time, loops_reduced, max_handle_force,
///                                        excessive_force_time
///   GAGES-C clear field:                 clear_view, red_out_count
///   GAGES-C instrumentation:             not scored until instruments exist
///   GAGES-C quality of examination:      mucosa_visualised, effective_withdrawal_time, lesions_detected,
///                                        lesions_missed
///   DOPS scope handling:                 max_handle_force, mean_handle_force, max_handle_torque,
///   tip_path_length DOPS tip control:                    clear_view, red_out_count DOPS loop management:
///   loop_count, looped_time, loops_reduced DOPS pain management:                discomfort_peak,
///   discomfort_moderate_share DOPS pace and progress:              max_insertion, time_to_cecum,
///   insertion_efficiency DOPS visualisation:                  mucosa_visualised, effective_withdrawal_time
///   DOPS pathology recognition:          lesions_detected, lesions_missed
///   DOPS complications:                  perforation, excessive_force_time
/// Composite: 100 x the mean proficiency over every benchmarked metric.

#include "scoring/Benchmarks.h"

#include <span>

namespace colonosim::scoring {

struct DomainMapping {
    std::string_view key;  ///< score name stored in the database
    std::string_view title;
    int top;  ///< 5 for GAGES-C, 4 for DOPS
    std::vector<std::string_view> metrics;
};

[[nodiscard]] const std::vector<DomainMapping>& domainMappings();

/// "composite" (0-100) and every scored domain and item.
[[nodiscard]] std::map<std::string, double> scoreSession(const MetricValues& values,
                                                         const BenchmarkSet& benchmarks);

}  // namespace colonosim::scoring
