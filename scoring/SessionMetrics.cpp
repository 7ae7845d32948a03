#include "scoring/SessionMetrics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace colonosim::scoring {

namespace {
std::string loopMetric(procedure::LoopKind kind)
{
    switch (kind) {
    case procedure::LoopKind::N: return "loops_n";
    case procedure::LoopKind::Alpha: return "loops_alpha";
    case procedure::LoopKind::ReverseAlpha: return "loops_reverse_alpha";
    case procedure::LoopKind::GammaDeepTransverse: return "loops_gamma";
    case procedure::LoopKind::ReverseSplenic: return "loops_reverse_splenic";
    case procedure::LoopKind::None: break;
    }
    return {};
}

procedure::LoopKind loopFromDetail(const std::string& detail)
{
    for (auto kind : {procedure::LoopKind::N, procedure::LoopKind::Alpha, procedure::LoopKind::ReverseAlpha,
                      procedure::LoopKind::GammaDeepTransverse, procedure::LoopKind::ReverseSplenic}) {
        if (procedure::loopName(kind) == detail) {
            return kind;
        }
    }
    return procedure::LoopKind::None;
}

/// Intervals from start / end events: an end without a start is ignored.
struct Intervals {
    std::vector<std::pair<double, double>> closed;
    double open = -1.0;  ///< start of the interval in progress; < 0: none
    void start(double time) { open = time; }
    void end(double time)
    {
        if (open >= 0.0) {
            closed.emplace_back(open, time);
            open = -1.0;
        }
    }
};

/// Length of the union of the intervals of `a` and `b` after `from`
/// (overlapping red-out and cleaning count once).
double unionAfter(std::vector<std::pair<double, double>> a, const std::vector<std::pair<double, double>>& b,
                  double from)
{
    a.insert(a.end(), b.begin(), b.end());
    std::sort(a.begin(), a.end());
    double total = 0.0, reached = from;
    for (const auto& [start, stop] : a) {
        const double lo = std::max(start, reached);
        if (stop > lo) {
            total += stop - lo;
            reached = stop;
        }
    }
    return total;
}
}  // namespace

MetricValues computeMetrics(const procedure::Recording& recording, const ScoringContext& context)
{
    params::require("scoring", ScoringContext::moderateDiscomfortSpec, context.moderateDiscomfort);
    params::require("scoring", ScoringContext::mucosaBinSpec, context.mucosaBin);
    MetricValues m;
    const auto& samples = recording.samples;
    const double end = samples.empty() ? 0.0 : samples.back().time;
    m["total_time"] = end;

    // Events: cecum, red-out intervals, loops, perforation, lesion marks.
    double cecum = -1.0;
    Intervals redOuts, cleanings;
    int loops = 0, reduced = 0, falseMarks = 0;
    std::map<std::string, double> firstInView, firstMark;  // by lesion name
    bool perforation = false;
    for (const char* name :
         {"loops_n", "loops_alpha", "loops_reverse_alpha", "loops_gamma", "loops_reverse_splenic"}) {
        m[name] = 0.0;
    }
    for (const auto& e : recording.events) {
        switch (e.kind) {
        case procedure::EventKind::CecumReached:
            if (cecum < 0.0) {
                cecum = e.time;
            }
            break;
        case procedure::EventKind::RedOutStart: redOuts.start(e.time); break;
        case procedure::EventKind::RedOutEnd: redOuts.end(e.time); break;
        case procedure::EventKind::CleaningStart: cleanings.start(e.time); break;
        case procedure::EventKind::CleaningEnd: cleanings.end(e.time); break;
        case procedure::EventKind::LoopFormed: {
            ++loops;
            const std::string metric = loopMetric(loopFromDetail(e.detail));
            if (!metric.empty()) {
                m[metric] += 1.0;
            }
            break;
        }
        case procedure::EventKind::LoopResolved: ++reduced; break;
        case procedure::EventKind::Perforation: perforation = true; break;
        case procedure::EventKind::LesionInView: firstInView.emplace(e.detail, e.time); break;
        case procedure::EventKind::LesionMarked:
            if (firstInView.count(e.detail) != 0) {
                firstMark.emplace(e.detail, e.time);
            } else {
                ++falseMarks;
            }
            break;
        default: break;
        }
    }
    redOuts.end(end);  // an interval still open when the session ends closes there
    cleanings.end(end);
    double redOutTime = 0.0;
    for (const auto& [a, b] : redOuts.closed) {
        redOutTime += b - a;
    }
    auto inRedOut = [&](double t) {
        return std::any_of(redOuts.closed.begin(), redOuts.closed.end(),
                           [t](const auto& r) { return t >= r.first && t < r.second; });
    };

    m["cecal_intubation"] = cecum >= 0.0 ? 1.0 : 0.0;
    if (cecum >= 0.0) {
        m["time_to_cecum"] = cecum;
    }
    m["withdrawal_time"] = cecum >= 0.0 ? end - cecum : 0.0;
    m["effective_withdrawal_time"] =
        cecum >= 0.0 ? std::max(0.0, end - cecum - unionAfter(redOuts.closed, cleanings.closed, cecum)) : 0.0;
    m["clear_view"] = end > 0.0 ? 1.0 - redOutTime / end : 0.0;
    m["red_out_count"] = static_cast<double>(redOuts.closed.size());
    m["loop_count"] = loops;
    m["loops_reduced"] = std::min(reduced, loops);
    m["perforation"] = perforation ? 1.0 : 0.0;
    m["lesions_present"] = context.lesionsPresent;
    m["lesions_detected"] = static_cast<double>(std::min<size_t>(firstMark.size(), context.lesionsPresent));
    m["lesions_missed"] = context.lesionsPresent - m["lesions_detected"];
    m["false_lesion_marks"] = falseMarks;
    if (!firstMark.empty()) {
        double sum = 0.0;
        for (const auto& [lesion, marked] : firstMark) {
            sum += marked - firstInView.at(lesion);
        }
        m["time_to_detection"] = sum / static_cast<double>(firstMark.size());
    }

    // Samples.
    const auto bins = static_cast<size_t>(std::ceil(context.colonLength / context.mucosaBin));
    std::vector<bool> seen(bins, false);
    double looped = 0.0, excessive = 0.0, moderate = 0.0;
    double maxForce = 0.0, sumForce = 0.0, maxTorque = 0.0, sumTorque = 0.0, peak = 0.0;
    double path = 0.0, maxInsertion = 0.0, forward = 0.0;
    for (size_t k = 0; k < samples.size(); ++k) {
        const auto& s = samples[k];
        const double dt = k + 1 < samples.size() ? samples[k + 1].time - s.time : 0.0;
        const double force = std::abs(s.handleForce);
        const double torque = std::abs(s.handleTorque);
        maxForce = std::max(maxForce, force);
        maxTorque = std::max(maxTorque, torque);
        sumForce += force;
        sumTorque += torque;
        peak = std::max(peak, s.discomfort);
        if (s.loop != procedure::LoopKind::None) {
            looped += dt;
        }
        if (force > context.excessiveForce) {
            excessive += dt;
        }
        if (s.discomfort >= context.moderateDiscomfort) {
            moderate += dt;
        }
        maxInsertion = std::max(maxInsertion, s.insertion);
        if (k > 0) {
            path += (s.tip - samples[k - 1].tip).norm();
            forward += std::max(0.0, s.insertion - samples[k - 1].insertion);
        }
        if (!inRedOut(s.time) && s.insertion >= 0.0) {
            const auto bin = static_cast<size_t>(s.insertion / context.mucosaBin);
            if (bin < bins) {
                seen[bin] = true;
            }
        }
    }
    const double n = std::max<size_t>(samples.size(), 1);
    m["looped_time"] = looped;
    m["excessive_force_time"] = excessive;
    m["discomfort_moderate_share"] = end > 0.0 ? moderate / end : 0.0;
    m["discomfort_peak"] = peak;
    m["max_handle_force"] = maxForce;
    m["mean_handle_force"] = sumForce / n;
    m["max_handle_torque"] = maxTorque;
    m["mean_handle_torque"] = sumTorque / n;
    m["tip_path_length"] = path;
    m["max_insertion"] = maxInsertion;
    m["insertion_efficiency"] = forward > 0.0 ? maxInsertion / forward : 0.0;
    if (context.mucosaSeen) {
        m["mucosa_visualised"] = std::clamp(*context.mucosaSeen, 0.0, 1.0);
        m["mucosa_from_renderer"] = 1.0;
    } else {
        m["mucosa_visualised"] = bins > 0 ? static_cast<double>(std::count(seen.begin(), seen.end(), true)) /
                                                static_cast<double>(bins)
                                          : 0.0;
        m["mucosa_from_renderer"] = 0.0;
    }
    return m;
}

}  // namespace colonosim::scoring
