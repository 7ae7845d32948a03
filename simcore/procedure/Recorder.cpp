#include "simcore/procedure/Recorder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

namespace colonosim::procedure {

std::string_view eventName(EventKind kind)
{
    switch (kind) {
    case EventKind::CecumReached: return "cecum_reached";
    case EventKind::LoopFormed: return "loop_formed";
    case EventKind::LoopResolved: return "loop_resolved";
    case EventKind::ExcessiveForceStart: return "excessive_force_start";
    case EventKind::ExcessiveForceEnd: return "excessive_force_end";
    case EventKind::Perforation: return "perforation";
    case EventKind::RedOutStart: return "red_out_start";
    case EventKind::RedOutEnd: return "red_out_end";
    case EventKind::LensWash: return "lens_wash";
    case EventKind::LesionMarked: return "lesion_marked";
    case EventKind::Retroflexion: return "retroflexion";
    case EventKind::InputRejected: return "input_rejected";
    case EventKind::DeviceConnected: return "device_connected";
    case EventKind::DeviceDisconnected: return "device_disconnected";
    case EventKind::LesionInView: return "lesion_in_view";
    case EventKind::LesionOutOfView: return "lesion_out_of_view";
    case EventKind::CleaningStart: return "cleaning_start";
    case EventKind::CleaningEnd: return "cleaning_end";
    case EventKind::ContactBleeding: return "contact_bleeding";
    case EventKind::LesionOnScreen: return "lesion_on_screen";
    case EventKind::LesionOffScreen: return "lesion_off_screen";
    }
    return "unknown";
}

std::string lesionName(int index)
{
    return "lesion " + std::to_string(index + 1);
}

namespace {
using R = RecorderParameters;
constexpr std::array<params::Field<R>, 4> kRecorderFields{{
    {&R::sampleIntervalSpec, &R::sampleInterval},
    {&R::excessiveForceSpec, &R::excessiveForce},
    {&R::redOutSpec, &R::redOutDistance},
    {&R::cecumDepthSpec, &R::cecumDepth},
}};
}  // namespace

std::span<const params::Field<RecorderParameters>> RecorderParameters::fields()
{
    return kRecorderFields;
}

void RecorderParameters::validate() const
{
    params::validateFields<RecorderParameters>("recorder", kRecorderFields, *this);
}

Recorder::Recorder(const RecorderParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
}

void Recorder::event(double time, EventKind kind, std::string detail)
{
    m_recording.events.push_back(RecordedEvent{time, kind, std::move(detail)});
}

void Recorder::record(const ProcedureFrame& f)
{
    if (f.inputRejected) {
        event(f.time, EventKind::InputRejected, f.inputRejection);
    }
    if (!m_cecumReached && f.tipArcLength >= m_parameters.colonLength - m_parameters.cecumDepth) {
        m_cecumReached = true;
        event(f.time, EventKind::CecumReached);
    }
    if (f.loop != m_loop) {
        if (m_loop != LoopKind::None) {
            event(f.time, EventKind::LoopResolved, std::string(loopName(m_loop)));
        }
        if (f.loop != LoopKind::None) {
            event(f.time, EventKind::LoopFormed, std::string(loopName(f.loop)));
        }
        m_loop = f.loop;
    }
    const bool excessive = f.handleForce > m_parameters.excessiveForce;
    if (excessive != m_excessive) {
        event(f.time, excessive ? EventKind::ExcessiveForceStart : EventKind::ExcessiveForceEnd);
        m_excessive = excessive;
    }
    if (f.perforation && !m_perforated) {
        event(f.time, EventKind::Perforation, std::string(geometry::segmentName(f.tipSegment)));
        m_perforated = true;
    }
    const bool redOut = f.lensWallDistance < m_parameters.redOutDistance;
    if (redOut != m_redOut) {
        event(f.time, redOut ? EventKind::RedOutStart : EventKind::RedOutEnd);
        m_redOut = redOut;
    }
    const bool pressed = (f.input.buttons & ~m_buttons) != 0;
    if (pressed && (f.input.buttons & ~m_buttons & kWater) != 0) {
        event(f.time, EventKind::LensWash);
    }
    constexpr std::uint8_t kCleaning = kWater | kSuction;
    const bool cleaning = (f.input.buttons & kCleaning) != 0;
    if (cleaning != ((m_buttons & kCleaning) != 0)) {
        event(f.time, cleaning ? EventKind::CleaningStart : EventKind::CleaningEnd);
    }
    for (std::uint32_t changed = f.lesionsInView ^ m_lesionsInView; changed != 0; changed &= changed - 1) {
        const int k = std::countr_zero(changed);  // lowest changed lesion first
        const bool inView = (f.lesionsInView & (std::uint32_t{1} << k)) != 0;
        event(f.time, inView ? EventKind::LesionInView : EventKind::LesionOutOfView, lesionName(k));
    }
    m_lesionsInView = f.lesionsInView;
    if (pressed && (f.input.buttons & ~m_buttons & kMarkLesion) != 0) {
        // The mark names the lesion in view (the first, when several are), or none.
        const std::string detail = f.lesionsInView != 0 ? lesionName(std::countr_zero(f.lesionsInView))
                                                        : std::string("none in view");
        event(f.time, EventKind::LesionMarked, detail);
    }
    m_buttons = f.input.buttons;
    // Retroflexion: the tip looks back along the colon (more than 135 degrees).
    const bool retroflexed = f.tipDirection.dot(f.colonTangentAtTip) < -0.7071;
    if (retroflexed && !m_retroflexed) {
        event(f.time, EventKind::Retroflexion, std::string(geometry::segmentName(f.tipSegment)));
    }
    m_retroflexed = retroflexed;

    if (f.time + 1e-12 >= m_nextSample) {
        m_recording.samples.push_back(quantizeSample(
            RecordedSample{f.time, f.input.insertion, f.tipPosition, f.tipSegment, f.handleForce,
                           f.handleTorque, f.maxWallForce, f.mesenteryStrain, f.discomfort, f.loop}));
        m_nextSample += m_parameters.sampleInterval;
    }
}

RecordedSample quantizeSample(const RecordedSample& sample)
{
    const auto round = [](double value, double step) { return std::nearbyint(value / step) * step; };
    using R = RecordingResolution;
    RecordedSample q = sample;
    for (int axis = 0; axis < 3; ++axis) {
        q.tip[axis] = round(sample.tip[axis], R::positionSpec.defaultValue);
    }
    q.handleForce = round(sample.handleForce, R::forceSpec.defaultValue);
    q.maxWallForce = round(sample.maxWallForce, R::forceSpec.defaultValue);
    q.handleTorque = round(sample.handleTorque, R::torqueSpec.defaultValue);
    q.mesenteryStrain = round(sample.mesenteryStrain, R::strainSpec.defaultValue);
    q.discomfort = round(sample.discomfort, R::discomfortSpec.defaultValue);
    return q;
}

void Recording::mergeEvents(const std::vector<RecordedEvent>& more)
{
    std::vector<RecordedEvent> merged;
    merged.reserve(events.size() + more.size());
    // std::merge takes from the first range at equal keys: the recorder's own events first.
    std::merge(events.begin(), events.end(), more.begin(), more.end(), std::back_inserter(merged),
               [](const RecordedEvent& a, const RecordedEvent& b) { return a.time < b.time; });
    events = std::move(merged);
}

std::string Recording::canonicalText() const
{
    std::ostringstream out;
    char buffer[64];
    const auto hex = [&](double v) {
        std::snprintf(buffer, sizeof(buffer), "%a", v);
        out << buffer << ' ';
    };
    for (const RecordedSample& s : samples) {
        out << "S ";
        for (const double v : {s.time, s.insertion, s.tip.x(), s.tip.y(), s.tip.z(), s.handleForce,
                               s.handleTorque, s.maxWallForce, s.mesenteryStrain, s.discomfort}) {
            hex(v);
        }
        out << geometry::segmentName(s.segment) << ' ' << loopName(s.loop) << '\n';
    }
    for (const RecordedEvent& e : events) {
        out << "E ";
        hex(e.time);
        out << eventName(e.kind) << ' ' << e.detail << '\n';
    }
    return out.str();
}

void Recording::writeCsv(const std::filesystem::path& samplesCsv,
                         const std::filesystem::path& eventsCsv) const
{
    std::ofstream s(samplesCsv);
    s.precision(17);
    s << "time_s,insertion_m,tip_x_m,tip_y_m,tip_z_m,segment,handle_force_N,handle_torque_Nm,max_wall_force_"
         "N,"
         "mesentery_strain,discomfort,loop\n";
    for (const RecordedSample& r : samples) {
        s << r.time << ',' << r.insertion << ',' << r.tip.x() << ',' << r.tip.y() << ',' << r.tip.z() << ','
          << geometry::segmentName(r.segment) << ',' << r.handleForce << ',' << r.handleTorque << ','
          << r.maxWallForce << ',' << r.mesenteryStrain << ',' << r.discomfort << ',' << loopName(r.loop)
          << '\n';
    }
    std::ofstream e(eventsCsv);
    e.precision(17);
    e << "time_s,event,detail\n";
    for (const RecordedEvent& r : events) {
        e << r.time << ',' << eventName(r.kind) << ',' << r.detail << '\n';
    }
    if (!s || !e) {
        throw std::runtime_error("cannot write the recording to " + samplesCsv.string() + " and " +
                                 eventsCsv.string());
    }
}

}  // namespace colonosim::procedure
