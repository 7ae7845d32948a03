#include "trainer_ui/reports/SessionReports.h"

#include "curricula/Curriculum.h"
#include "scoring/MetricDefinitions.h"

#include <QUuid>

#include <iomanip>
#include <set>
#include <sstream>

namespace colonosim::reports {

namespace {

std::vector<std::string> metricColumns()
{
    std::vector<std::string> columns;
    for (const auto& d : scoring::metricDefinitions()) {
        columns.emplace_back(d.name);
    }
    return columns;
}

}  // namespace

std::string csvReport(const std::vector<db::SessionRow>& sessions)
{
    std::set<std::string> scoreNames;
    for (const auto& s : sessions) {
        for (const auto& [name, value] : s.scores) {
            scoreNames.insert(name);
        }
    }
    const auto metrics = metricColumns();
    std::ostringstream out;
    out << std::setprecision(17) << "session,user,started_at,task,device,duration_s";
    for (const auto& m : metrics) {
        const auto* d = scoring::findMetric(m);
        out << ',' << m << " [" << d->unit << ']';
    }
    for (const auto& s : scoreNames) {
        out << ",score:" << s;
    }
    out << '\n';
    for (const auto& s : sessions) {
        out << s.id << ',' << s.user << ',' << s.startedAt << ',' << s.task << ',' << s.device << ','
            << s.duration;
        for (const auto& m : metrics) {
            out << ',';
            if (const auto it = s.metrics.find(m); it != s.metrics.end()) {
                out << it->second;
            }
        }
        for (const auto& name : scoreNames) {
            out << ',';
            if (const auto it = s.scores.find(name); it != s.scores.end()) {
                out << it->second;
            }
        }
        out << '\n';
    }
    return out.str();
}

namespace {
std::string isoDuration(double seconds)
{
    std::ostringstream out;
    out << "PT" << std::fixed << std::setprecision(2) << seconds << 'S';
    return out.str();
}

}  // namespace

nlohmann::json xapiReport(const std::vector<db::SessionRow>& sessions, const std::string& home)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    nlohmann::json statements = nlohmann::json::array();
    for (const auto& s : sessions) {
        const curricula::Task* task = curriculum.value->find(s.task);
        nlohmann::json metrics;
        for (const auto& [name, value] : s.metrics) {
            metrics[name] = value;
        }
        nlohmann::json result = {{"completion", true}, {"duration", isoDuration(s.duration)}};
        if (const auto it = s.scores.find("composite"); it != s.scores.end()) {
            result["score"] = {{"scaled", it->second / 100.0}, {"raw", it->second}, {"min", 0}, {"max", 100}};
        }
        if (const auto it = s.scores.find("benchmark_met"); it != s.scores.end()) {
            result["success"] = it->second > 0.5;
        }
        result["extensions"] = {{home + "/xapi/extensions/metrics", metrics},
                                {home + "/xapi/extensions/scores", s.scores}};
        statements.push_back({
            {"id", QUuid::createUuid().toString(QUuid::WithoutBraces).toStdString()},
            {"actor",
             {{"objectType", "Agent"},
              {"name", s.user},
              {"account", {{"homePage", home}, {"name", s.user}}}}},
            {"verb",
             {{"id", "http://adlnet.gov/expapi/verbs/completed"}, {"display", {{"en-US", "completed"}}}}},
            {"object",
             {{"objectType", "Activity"},
              {"id", home + "/xapi/activities/colonoscopy-core/" + s.task},
              {"definition",
               {{"name", {{"en-US", task ? task->title : s.task}}},
                {"type", "http://adlnet.gov/expapi/activities/simulation"}}}}},
            {"result", result},
            {"context",
             {{"platform", "colonosim"},
              {"extensions",
               {{home + "/xapi/extensions/session", s.id}, {home + "/xapi/extensions/device", s.device}}}}},
            {"timestamp", s.startedAt},
        });
    }
    return statements;
}

}  // namespace colonosim::reports
