#include "curricula/Certification.h"

#include "curricula/XmlRoot.h"
#include "scoring/MetricDefinitions.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace colonosim::curricula {

namespace {

double metricOf(const scoring::MetricValues& m, const std::string& name)
{
    const auto it = m.find(name);
    return it == m.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

}  // namespace

RuleSetRead parseRuleSet(const std::string& xml, const std::string& label)
{
    RuleSetRead result;
    auto error = [&](const tinyxml2::XMLElement* e, const std::string& message) {
        result.errors.push_back(label + ":" + std::to_string(e ? e->GetLineNum() : 0) + ": " + message);
    };
    tinyxml2::XMLDocument document;
    const tinyxml2::XMLElement* root = parseRoot(document, xml, label, "certification", result.errors);
    if (root == nullptr) {
        return result;
    }
    RuleSet set;
    set.name = root->Attribute("name") ? root->Attribute("name") : "";
    set.version = root->IntAttribute("version", 0);
    if (set.name.empty() || set.version < 1) {
        error(root, "<certification> needs a name and a version >= 1");
    }
    for (const auto* e = root->FirstChildElement("rule"); e; e = e->NextSiblingElement("rule")) {
        CertificationRule r;
        auto text = [&](const char* a) { return std::string(e->Attribute(a) ? e->Attribute(a) : ""); };
        r.id = text("id");
        r.description = text("description");
        r.source = text("source");
        if (r.id.empty() || r.description.empty() || r.source.empty()) {
            error(e, "a rule needs id, description and source (rule \"" + r.id + "\")");
        }
        const std::string kind = text("kind");
        if (kind == "count_at_least") {
            r.kind = RuleKind::CountAtLeast;
        } else if (kind == "share_at_least") {
            r.kind = RuleKind::ShareAtLeast;
        } else if (kind == "share_below") {
            r.kind = RuleKind::ShareBelow;
        } else if (kind == "median_at_least") {
            r.kind = RuleKind::MedianAtLeast;
        } else if (kind == "none_in_last") {
            r.kind = RuleKind::NoneInLast;
        } else {
            error(e, "kind = \"" + kind +
                         "\" is not one of count_at_least, share_at_least, share_below, median_at_least, "
                         "none_in_last");
        }
        r.metric = text("metric");
        r.among = text("among");
        for (const std::string& m : {r.metric, r.among}) {
            if (!m.empty() && !scoring::findMetric(m)) {
                error(e, "metric \"" + m + "\" is not a declared scoring metric");
            }
        }
        if (r.kind != RuleKind::CountAtLeast && r.metric.empty()) {
            error(e, "rule \"" + r.id + "\" of kind " + kind + " needs a metric");
        }
        r.atLeast = e->DoubleAttribute("at_least", 1.0);
        r.window = e->IntAttribute("window", 0);
        if (r.window < 0 || r.window > 100000) {
            error(e, "window = " + std::to_string(r.window) + " is out of range 0-100000");
        }
        r.value = e->DoubleAttribute("value", 0.0);
        const bool share = r.kind == RuleKind::ShareAtLeast || r.kind == RuleKind::ShareBelow;
        if (share && !(r.value >= 0.0 && r.value <= 1.0)) {
            error(e, "value = " + std::to_string(r.value) + " is out of range 0-1 for a share");
        }
        set.rules.push_back(std::move(r));
    }
    if (set.rules.empty()) {
        error(root, "the rule set has no rule");
    }
    if (result.errors.empty()) {
        result.value = std::move(set);
    }
    return result;
}

std::vector<RuleStatus> evaluate(const RuleSet& rules, const std::vector<scoring::MetricValues>& sessions)
{
    std::vector<RuleStatus> out;
    for (const CertificationRule& r : rules.rules) {
        std::vector<const scoring::MetricValues*> pool;
        for (const auto& s : sessions) {
            if (r.among.empty() || metricOf(s, r.among) > 0.0) {
                pool.push_back(&s);
            }
        }
        if (r.window > 0 && pool.size() > static_cast<size_t>(r.window)) {
            pool.erase(pool.begin(), pool.end() - r.window);
        }
        const int n = static_cast<int>(pool.size());
        const int positive = static_cast<int>(std::count_if(
            pool.begin(), pool.end(), [&](const auto* s) { return metricOf(*s, r.metric) >= r.atLeast; }));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        RuleStatus status{&r, false, nan, n};
        switch (r.kind) {
        case RuleKind::CountAtLeast:
            status.observed = static_cast<double>(sessions.size());
            status.met = status.observed >= r.value;
            status.sessions = static_cast<int>(sessions.size());
            break;
        case RuleKind::ShareAtLeast:
            // Too few sessions for the window: not met (the window must be filled).
            status.observed = n > 0 ? static_cast<double>(positive) / n : nan;
            status.met = n > 0 && (r.window == 0 || n >= r.window) && status.observed >= r.value;
            break;
        case RuleKind::ShareBelow:
            status.observed = n > 0 ? static_cast<double>(positive) / n : nan;
            status.met = n > 0 && (r.window == 0 || n >= r.window) && status.observed < r.value;
            break;
        case RuleKind::MedianAtLeast: {
            std::vector<double> v;
            for (const auto* s : pool) {
                if (const double x = metricOf(*s, r.metric); !std::isnan(x)) {
                    v.push_back(x);
                }
            }
            if (!v.empty()) {
                std::sort(v.begin(), v.end());
                const size_t m = v.size() / 2;
                status.observed = v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
                status.met = status.observed >= r.value;
            }
            break;
        }
        case RuleKind::NoneInLast:
            status.observed = positive;
            status.met = n > 0 && (r.window == 0 || n >= r.window) && positive == 0;
            break;
        }
        out.push_back(status);
    }
    return out;
}

}  // namespace colonosim::curricula
