#include "trainer_ui/reports/ProgressReport.h"

#include "curricula/Curriculum.h"
#include "curricula/Progression.h"
#include "scoring/LearningCurve.h"

#include <cmath>
#include <cstdio>

namespace colonosim::reports {

nlohmann::json progressReport(db::Database& database, db::Records& records, const db::Actor& actor,
                              const std::string& user)
{
    return progressReport(records.sessions(actor, user), user,
                          db::CertificationRules(database).active(actor));
}

nlohmann::json progressReport(const std::vector<db::SessionRow>& sessions, const std::string& user,
                              const db::ActiveRuleSet& rules)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    std::vector<curricula::Attempt> attempts;
    std::vector<scoring::MetricValues> metrics;
    std::vector<bool> failures;
    for (const db::SessionRow& s : sessions) {
        const auto met = s.scores.find("benchmark_met");
        attempts.push_back({s.task, met != s.scores.end() && met->second > 0.5});
        metrics.push_back(s.metrics);
        const auto cecum = s.metrics.find("cecal_intubation");
        failures.push_back(cecum == s.metrics.end() || cecum->second < 0.5);
    }
    nlohmann::json out;
    out["user"] = user;
    out["completed_sessions"] = sessions.size();
    const auto states = curricula::progression(*curriculum.value, attempts);
    for (const curricula::Task& t : curriculum.value->tasks) {
        nlohmann::json task = {{"id", t.id},
                               {"module", t.module},
                               {"title", t.title},
                               {"state", curricula::stateName(states.at(t.id))}};
        if (!t.available) {
            task["why"] = t.unavailableReason;
        }
        out["tasks"].push_back(task);
    }
    const scoring::CusumParameters parameters;
    const scoring::LearningCurve curve = scoring::learningCurve(failures, parameters);
    out["learning_curve"] = {{"outcome", "failure = cecum not reached"},
                             {"acceptable_failure_rate", parameters.acceptable},
                             {"unacceptable_failure_rate", parameters.unacceptable},
                             {"cusum", curve.cusum},
                             {"cusum_h1", parameters.upperLimit()},
                             {"lc_cusum", curve.lcCusum},
                             {"lc_cusum_h", parameters.lcLimit()},
                             {"competent_at", curve.competentAt},
                             {"unacceptable_at", curve.unacceptableAt}};
    out["certification_rule_set"] = {{"name", rules.stored.name}, {"version", rules.stored.version}};
    for (const curricula::RuleStatus& r : curricula::evaluate(rules.rules, metrics)) {
        out["certification"].push_back(
            {{"rule", r.rule->id},
             {"description", r.rule->description},
             {"met", r.met},
             {"observed", std::isnan(r.observed) ? nlohmann::json() : nlohmann::json(r.observed)},
             {"sessions", r.sessions},
             {"window", r.rule->window},
             {"source", r.rule->source}});
    }
    return out;
}

std::string ruleSetLabel(const nlohmann::json& progress)
{
    const auto& set = progress["certification_rule_set"];
    return set["name"].get<std::string>() + ", version " + std::to_string(set["version"].get<int>());
}

std::string observedText(double observed)
{
    if (std::isnan(observed)) {
        return "none yet";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", observed);
    return text;
}

std::string sessionsText(const nlohmann::json& rule)
{
    const int sessions = rule["sessions"].get<int>();
    const int window = rule.value("window", 0);
    if (window > 0 && sessions < window) {
        return std::to_string(sessions) + " of the " + std::to_string(window) + " it needs";
    }
    return std::to_string(sessions);
}

}  // namespace colonosim::reports
