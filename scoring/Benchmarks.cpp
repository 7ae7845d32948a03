#include "scoring/Benchmarks.h"

#include "scoring/MetricDefinitions.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colonosim::scoring {

namespace {
double spread(const MetricBenchmark& b)
{
    return std::max({b.sd, 0.05 * std::abs(b.mean), 1e-12});
}
}  // namespace

double BenchmarkSet::limit(const std::string& metric) const
{
    const MetricBenchmark& b = metrics.at(metric);
    const MetricDefinition* d = findMetric(metric);
    const double s = spread(b);
    return d && d->better == Better::Higher ? b.mean - k * s : b.mean + k * s;
}

std::optional<double> BenchmarkSet::proficiency(const std::string& metric, double value) const
{
    const auto it = metrics.find(metric);
    const MetricDefinition* d = findMetric(metric);
    if (it == metrics.end() || !d || d->better == Better::Neither) {
        return std::nullopt;
    }
    const double s = spread(it->second);
    const double beyond = d->better == Better::Higher ? limit(metric) - value : value - limit(metric);
    return std::clamp(1.0 - beyond / (3.0 * s), 0.0, 1.0);
}

bool BenchmarkSet::met(const MetricValues& values) const
{
    for (const auto& [name, b] : metrics) {
        const auto it = values.find(name);
        const auto p = it == values.end() ? std::optional<double>(0.0) : proficiency(name, it->second);
        if (p && *p < 1.0) {
            return false;
        }
    }
    return true;
}

std::string BenchmarkSet::toJson() const
{
    nlohmann::json j;
    j["name"] = name;
    j["version"] = version;
    j["k"] = k;
    for (const auto& [metric, b] : metrics) {
        j["metrics"][metric] = {{"mean", b.mean}, {"sd", b.sd}, {"runs", b.runs}};
    }
    return j.dump(2);
}

BenchmarkSet BenchmarkSet::fromJson(const std::string& text)
{
    BenchmarkSet set;
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        set.name = j.at("name").get<std::string>();
        set.version = j.at("version").get<int>();
        set.k = j.at("k").get<double>();
        params::require("benchmark", kSpec, set.k);
        if (set.version < 1) {
            throw std::invalid_argument("benchmark version " + std::to_string(set.version) +
                                        " is out of range >= 1");
        }
        for (const auto& [metric, b] : j.at("metrics").items()) {
            if (!findMetric(metric)) {
                throw std::invalid_argument("benchmark metric \"" + metric + "\" is not a declared metric");
            }
            set.metrics[metric] = {b.at("mean").get<double>(), b.at("sd").get<double>(),
                                   b.at("runs").get<int>()};
        }
    } catch (const nlohmann::json::exception& error) {
        throw std::invalid_argument(std::string("benchmark set: ") + error.what());
    }
    return set;
}

BenchmarkSet deriveBenchmarks(const std::string& name, int version, double k,
                              const std::vector<MetricValues>& expertRuns)
{
    params::require("benchmark", BenchmarkSet::kSpec, k);
    BenchmarkSet set{name, version, k, {}};
    for (const MetricDefinition& d : metricDefinitions()) {
        if (d.better == Better::Neither) {
            continue;
        }
        std::vector<double> values;
        for (const MetricValues& run : expertRuns) {
            if (const auto it = run.find(std::string(d.name)); it != run.end()) {
                values.push_back(it->second);
            }
        }
        if (values.empty()) {
            continue;
        }
        double mean = 0.0;
        for (double v : values) {
            mean += v;
        }
        mean /= static_cast<double>(values.size());
        double var = 0.0;
        for (double v : values) {
            var += (v - mean) * (v - mean);
        }
        const double sd = values.size() > 1 ? std::sqrt(var / static_cast<double>(values.size() - 1)) : 0.0;
        set.metrics[std::string(d.name)] = {mean, sd, static_cast<int>(values.size())};
    }
    return set;
}

}  // namespace colonosim::scoring
