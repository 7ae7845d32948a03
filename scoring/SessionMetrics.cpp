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

/// Lesion detection: which lesions a mark found, when each was first in
/// view, and the marks that found none.
struct Detection {
    std::map<std::string, double> firstMark, firstSeen;  // by lesion name
    int falseMarks = 0;
    bool fromRenderer = false;
};

/// With the renderer's LesionOnScreen / LesionOffScreen events (a session the
/// renderer watched), a mark at t finds a lesion on screen at t within
/// `tolerance` (the renderer looks 10 times a second): the lesion the mark
/// names when it is one of them, else the first not yet found. Without
/// them, the loop's own signal: the lesion the mark names (LesionInView,
/// no occlusion test).
Detection detectLesions(const std::vector<procedure::RecordedEvent>& events, double end, double tolerance)
{
    using procedure::EventKind;
    Detection d;
    d.fromRenderer = std::any_of(events.begin(), events.end(), [](const auto& e) {
        return e.kind == EventKind::LesionOnScreen || e.kind == EventKind::LesionOffScreen;
    });
    std::map<std::string, Intervals> onScreen;
    std::vector<const procedure::RecordedEvent*> marks;
    for (const auto& e : events) {
        if (e.kind == EventKind::LesionMarked) {
            marks.push_back(&e);
        } else if (!d.fromRenderer && e.kind == EventKind::LesionInView) {
            d.firstSeen.emplace(e.detail, e.time);
        } else if (d.fromRenderer && e.kind == EventKind::LesionOnScreen) {
            d.firstSeen.emplace(e.detail, e.time);
            onScreen[e.detail].start(e.time);
        } else if (d.fromRenderer && e.kind == EventKind::LesionOffScreen) {
            onScreen[e.detail].end(e.time);
        }
    }
    if (!d.fromRenderer) {
        for (const auto* mark : marks) {
            if (d.firstSeen.count(mark->detail) != 0) {
                d.firstMark.emplace(mark->detail, mark->time);
            } else {
                ++d.falseMarks;
            }
        }
        return d;
    }
    for (auto& [lesion, intervals] : onScreen) {
        intervals.end(end);  // still on screen when the session ended
    }
    for (const auto* mark : marks) {
        const double t = mark->time;
        std::vector<std::string> candidates;  // on screen at the mark, in name order
        for (const auto& [lesion, intervals] : onScreen) {
            if (std::any_of(intervals.closed.begin(), intervals.closed.end(), [&](const auto& i) {
                    return t >= i.first - tolerance && t <= i.second + tolerance;
                })) {
                candidates.push_back(lesion);
            }
        }
        if (candidates.empty()) {
            ++d.falseMarks;
            continue;
        }
        auto notFound = [&](const std::string& lesion) { return d.firstMark.count(lesion) == 0; };
        std::string found;
        if (std::find(candidates.begin(), candidates.end(), mark->detail) != candidates.end() &&
            notFound(mark->detail)) {
            found = mark->detail;
        } else if (const auto it = std::find_if(candidates.begin(), candidates.end(), notFound);
                   it != candidates.end()) {
            found = *it;
        }
        if (!found.empty()) {
            d.firstMark.emplace(found, t);
        }  // else a lesion found before, marked again: neither new nor false
    }
    return d;
}
}  // namespace

ScoringContext storedContext(const MetricValues& stored)
{
    ScoringContext context;
    if (const auto it = stored.find("lesions_present"); it != stored.end()) {
        context.lesionsPresent = static_cast<int>(it->second);
    }
    if (const auto it = stored.find("colon_length"); it != stored.end()) {
        context.colonLength = it->second;
    }
    if (const auto it = stored.find("mucosa_from_renderer"); it != stored.end() && it->second > 0.5) {
        context.mucosaSeen = stored.at("mucosa_visualised");
    }
    return context;
}

MetricValues computeMetrics(const procedure::Recording& recording, const ScoringContext& context)
{
    params::require("scoring", ScoringContext::moderateDiscomfortSpec, context.moderateDiscomfort);
    params::require("scoring", ScoringContext::mucosaBinSpec, context.mucosaBin);
    params::require("scoring", ScoringContext::sightingToleranceSpec, context.sightingTolerance);
    params::require("scoring", ScoringContext::colonLengthSpec, context.colonLength);
    MetricValues m;
    const auto& samples = recording.samples;
    const double end = samples.empty() ? 0.0 : samples.back().time;
    m["total_time"] = end;

    // Events: cecum, red-out intervals, loops, perforation, lesion marks.
    double cecum = -1.0;
    Intervals redOuts, cleanings;
    int loops = 0, reduced = 0;
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
    const Detection detection = detectLesions(recording.events, end, context.sightingTolerance);
    m["lesions_present"] = context.lesionsPresent;
    m["colon_length"] = context.colonLength;
    m["lesions_detected"] =
        static_cast<double>(std::min<size_t>(detection.firstMark.size(), context.lesionsPresent));
    m["lesions_missed"] = context.lesionsPresent - m["lesions_detected"];
    m["false_lesion_marks"] = detection.falseMarks;
    m["lesions_from_renderer"] = detection.fromRenderer ? 1.0 : 0.0;
    if (!detection.firstMark.empty()) {
        double sum = 0.0;
        for (const auto& [lesion, marked] : detection.firstMark) {
            sum += std::max(0.0, marked - detection.firstSeen.at(lesion));
        }
        m["time_to_detection"] = sum / static_cast<double>(detection.firstMark.size());
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
