#include "scoring/DomainScores.h"

namespace colonosim::scoring {

const std::vector<DomainMapping>& domainMappings()
{
    static const std::vector<DomainMapping> all = {
        {"gages_navigation",
         "GAGES-C scope navigation",
         5,
         {"max_insertion", "insertion_efficiency", "tip_path_length", "time_to_cecum"}},
        {"gages_advancement",
         "GAGES-C strategies for scope advancement",
         5,
         {"loop_count", "looped_time", "loops_reduced", "max_handle_force", "excessive_force_time"}},
        {"gages_clear_field", "GAGES-C clear field", 5, {"clear_view", "red_out_count"}},
        {"gages_instrumentation", "GAGES-C instrumentation (not scored until instruments exist)", 5, {}},
        {"gages_quality",
         "GAGES-C quality of examination",
         5,
         {"mucosa_visualised", "effective_withdrawal_time", "lesions_detected", "lesions_missed"}},
        {"dops_scope_handling",
         "DOPS scope handling",
         4,
         {"max_handle_force", "mean_handle_force", "max_handle_torque", "tip_path_length"}},
        {"dops_tip_control", "DOPS tip control", 4, {"clear_view", "red_out_count"}},
        {"dops_loop_management", "DOPS loop management", 4, {"loop_count", "looped_time", "loops_reduced"}},
        {"dops_pain_management", "DOPS pain management", 4, {"discomfort_peak", "discomfort_moderate_share"}},
        {"dops_pace_progress",
         "DOPS pace and progress",
         4,
         {"max_insertion", "time_to_cecum", "insertion_efficiency"}},
        {"dops_visualisation", "DOPS visualisation", 4, {"mucosa_visualised", "effective_withdrawal_time"}},
        {"dops_pathology_recognition",
         "DOPS pathology recognition",
         4,
         {"lesions_detected", "lesions_missed"}},
        {"dops_complications", "DOPS complications", 4, {"perforation", "excessive_force_time"}},
    };
    return all;
}

std::map<std::string, double> scoreSession(const MetricValues& values, const BenchmarkSet& benchmarks)
{
    auto proficiencyOf = [&](const std::string& metric) -> std::optional<double> {
        if (!benchmarks.metrics.contains(metric)) {
            return std::nullopt;
        }
        const auto it = values.find(metric);
        // A benchmarked metric the run lacks (the cecum never reached) scores 0.
        return it == values.end() ? std::optional<double>(0.0) : benchmarks.proficiency(metric, it->second);
    };
    std::map<std::string, double> scores;
    for (const DomainMapping& domain : domainMappings()) {
        double sum = 0.0;
        int n = 0;
        for (std::string_view metric : domain.metrics) {
            if (const auto p = proficiencyOf(std::string(metric))) {
                sum += *p;
                ++n;
            }
        }
        if (n > 0) {
            scores[std::string(domain.key)] = 1.0 + (domain.top - 1) * sum / n;
        }
    }
    double sum = 0.0;
    int n = 0;
    for (const auto& [metric, b] : benchmarks.metrics) {
        if (const auto p = proficiencyOf(metric)) {
            sum += *p;
            ++n;
        }
    }
    scores["composite"] = n > 0 ? 100.0 * sum / n : 0.0;
    return scores;
}

}  // namespace colonosim::scoring
