#pragma once
/// \file
/// The recording of a session: samples at a fixed rate (100 Hz by default)
/// and events at the exact loop step they happen.
///
/// Samples: insertion depth, tip position, colon segment at the tip, handle
/// force and torque, maximum wall contact force, mesentery stretch,
/// discomfort and loop state. Events, detected on edges of the per-step
/// frame: cecum reached, loop formed / resolved (with its type), excessive
/// handle force start / end, perforation, red-out start / end (lens against
/// the wall), lens wash and lesion marked (button presses), cleaning start /
/// end (water or suction held: the first step with either held, the first
/// step with neither; a session ending while cleaning has no end event and
/// is closed at its end by whoever reads it), retroflexion
/// (tip pointing back along the colon), device input rejected, and input
/// device connected / disconnected (with its name: which device drove the session).
///
/// The canonical text form writes every double as a hexadecimal float, so
/// two recordings are bit-identical exactly when their texts are equal.

#include "simcore/geometry/Segment.h"
#include "simcore/params/Parameter.h"
#include "simcore/procedure/DeviceInput.h"
#include "simcore/procedure/LoopDetector.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace colonosim::procedure {

/// What the procedure loop knows after one loop step.
struct ProcedureFrame {
    double time = 0.0;  ///< s since the session started
    InputSample input;
    Eigen::Vector3d tipPosition = Eigen::Vector3d::Zero();    ///< m
    Eigen::Vector3d tipDirection = Eigen::Vector3d::UnitZ();  ///< unit, the camera's view
    double tipArcLength = 0.0;                                ///< along the colon, m
    geometry::Segment tipSegment = geometry::Segment::Rectum;
    Eigen::Vector3d colonTangentAtTip = Eigen::Vector3d::UnitZ();  ///< unit, towards the cecum
    double lensWallDistance = 1.0;                                 ///< from the lens to the nearest wall, m
    double handleForce = 0.0;                                      ///< axial, + resisting insertion, N
    double handleTorque = 0.0;                                     ///< about the shaft, N m
    double maxWallForce = 0.0;                                     ///< largest scope-wall contact force, N
    double mesenteryStrain = 0.0;                                  ///< largest, 1
    double discomfort = 0.0;                                       ///< 0-10
    bool perforation = false;
    LoopKind loop = LoopKind::None;
    std::uint32_t lesionsInView = 0;  ///< bit k: lesion k of the case is in view (LesionView.h)
    bool inputRejected = false;
    std::string inputRejection;
};

struct RecordedSample {
    double time, insertion;
    Eigen::Vector3d tip;
    geometry::Segment segment;
    double handleForce, handleTorque, maxWallForce, mesenteryStrain, discomfort;
    LoopKind loop;
};

enum class EventKind {
    CecumReached,
    LoopFormed,
    LoopResolved,
    ExcessiveForceStart,
    ExcessiveForceEnd,
    Perforation,
    RedOutStart,
    RedOutEnd,
    LensWash,
    LesionMarked,
    Retroflexion,
    InputRejected,
    DeviceConnected,     ///< detail: the input device's name
    DeviceDisconnected,  ///< detail: the input device's name
    LesionInView,        ///< detail: "lesion K" (K from 1, the case's order)
    LesionOutOfView,     ///< detail: "lesion K"
    CleaningStart,       ///< water (lens wash / jet) or suction held
    CleaningEnd,         ///< neither held any more
    ContactBleeding,     ///< a contact bleeding mark appeared (BleedingMarks.h)
    /// The renderer's picture shows lesion K (detail "lesion K"): one of its
    /// triangles has a pixel in the coverage ID buffer, depth-tested, so a
    /// fold in front hides it. Noted by cli::SessionCoverage at its updates
    /// (10 Hz), not by the loop; at its first update every lesion gets
    /// LesionOnScreen or LesionOffScreen, so a recording watched by the
    /// renderer says so even when no lesion ever came on screen.
    LesionOnScreen,
    LesionOffScreen,  ///< detail: "lesion K"; the renderer's picture no longer shows it
};
/// The last EventKind, for range checks of stored codes.
inline constexpr EventKind kLastEventKind = EventKind::LesionOffScreen;
[[nodiscard]] std::string_view eventName(EventKind kind);
/// "lesion K" for the lesion of index `index` (K = index + 1), as events name it.
[[nodiscard]] std::string lesionName(int index);

struct RecordedEvent {
    double time;
    EventKind kind;
    std::string detail;
};

struct RecorderParameters {
    static constexpr params::ParameterSpec sampleIntervalSpec{"sampleInterval",
                                                              "s",
                                                              0.01,
                                                              1e-3,
                                                              0.01,
                                                              "time between recorded samples (>= 100 Hz)",
                                                              "issue requirement: samples at >= 100 Hz"};
    static constexpr params::ParameterSpec excessiveForceSpec{
        "excessiveForce",
        "N",
        15.0,
        1.0,
        100.0,
        "handle force counted as excessive",
        "Appleyard et al. 2000: forces above ~10 N occur only 5% of the time; peak push ~43 N"};
    static constexpr params::ParameterSpec redOutSpec{"redOutDistance",
                                                      "m",
                                                      0.003,
                                                      0.0,
                                                      0.02,
                                                      "lens-to-wall distance below which the view is red",
                                                      "assumption: the lens touches the mucosa"};
    static constexpr params::ParameterSpec cecumDepthSpec{
        "cecumDepth",
        "m",
        0.02,
        0.0,
        0.1,
        "distance before the end of the colon at which the tip counts as in the cecum",
        "reference/clinical-assessment.md: the cecum is reached when its landmarks (ileocecal valve, "
        "appendiceal orifice) are in view; assumption: from 2 cm, well within the 5 cm working distance, "
        "the tip sees the cecal pole"};
    double sampleInterval = sampleIntervalSpec.defaultValue;
    double excessiveForce = excessiveForceSpec.defaultValue;
    double redOutDistance = redOutSpec.defaultValue;
    double cecumDepth = cecumDepthSpec.defaultValue;
    double colonLength = 1.66;  ///< m, from the anatomy

    /// The declared fields (colonLength comes from the anatomy, not a setting).
    [[nodiscard]] static std::span<const params::Field<RecorderParameters>> fields();
    /// Throws ParameterError naming the field, the value and the range.
    void validate() const;
};

/// The steps the recorded sample values are rounded to, so that the stored
/// recording (the database keeps it for scoring and re-scoring) is the one
/// the metrics were computed from, and compact: the bits below these steps
/// are noise of the solvers, not information. Powers of two, so every
/// rounded value is exact in binary and the round trip through storage is
/// bit for bit.
struct RecordingResolution {
    static constexpr params::ParameterSpec positionSpec{
        "recordedPositionResolution",
        "m",
        9.5367431640625e-7,
        9.5367431640625e-7,
        9.5367431640625e-7,
        "step of the recorded tip position: 2^-20 m (0.95 um)",
        "assumption: far finer than the 5 cm working distance and mm-scale path metrics (tip path "
        "length); finer than electromagnetic scope tracking (~1 mm)"};
    static constexpr params::ParameterSpec forceSpec{
        "recordedForceResolution",
        "N",
        9.765625e-4,
        9.765625e-4,
        9.765625e-4,
        "step of the recorded handle and wall forces: 2^-10 N (1 mN)",
        "assumption: a thousandth of the 1-15 N range of insertion forces (Appleyard et al. 2000)"};
    static constexpr params::ParameterSpec torqueSpec{
        "recordedTorqueResolution",
        "N m",
        6.103515625e-5,
        6.103515625e-5,
        6.103515625e-5,
        "step of the recorded handle torque: 2^-14 N m (0.06 mN m)",
        "assumption: a thousandth of the ~0.1 N m torques of loop reduction"};
    static constexpr params::ParameterSpec strainSpec{
        "recordedStrainResolution",
        "1",
        9.5367431640625e-7,
        9.5367431640625e-7,
        9.5367431640625e-7,
        "step of the recorded mesentery strain: 2^-20",
        "assumption: far below the strains at which discomfort starts (a few percent)"};
    static constexpr params::ParameterSpec discomfortSpec{
        "recordedDiscomfortResolution",
        "1",
        9.765625e-4,
        9.765625e-4,
        9.765625e-4,
        "step of the recorded discomfort score (0-10): 2^-10",
        "assumption: far below one step of the 5-point clinical comfort scale (2 points of 10)"};
};

/// `sample` with its values rounded to RecordingResolution.
[[nodiscard]] RecordedSample quantizeSample(const RecordedSample& sample);

struct Recording {
    std::vector<RecordedSample> samples;
    std::vector<RecordedEvent> events;

    /// Hexadecimal floats, one line per sample and per event.
    [[nodiscard]] std::string canonicalText() const;
    /// Adds `more` (each in time order) to the events, keeping them in time
    /// order; at equal times the events already here come first.
    void mergeEvents(const std::vector<RecordedEvent>& more);
    void writeCsv(const std::filesystem::path& samplesCsv, const std::filesystem::path& eventsCsv) const;
};

class Recorder {
public:
    explicit Recorder(const RecorderParameters& parameters);

    /// Called once per loop step, in order.
    void record(const ProcedureFrame& frame);
    /// An event that does not come from the frame (an input device came or went).
    void note(double time, EventKind kind, std::string detail) { event(time, kind, std::move(detail)); }
    [[nodiscard]] const Recording& recording() const { return m_recording; }
    [[nodiscard]] const RecorderParameters& parameters() const { return m_parameters; }
    /// Whether the cecum_reached event has been recorded.
    [[nodiscard]] bool cecumReached() const { return m_cecumReached; }

private:
    void event(double time, EventKind kind, std::string detail = {});

    RecorderParameters m_parameters;
    Recording m_recording;
    double m_nextSample = 0.0;
    std::uint32_t m_lesionsInView = 0;
    bool m_cecumReached = false;
    bool m_excessive = false;
    bool m_redOut = false;
    bool m_retroflexed = false;
    bool m_perforated = false;
    LoopKind m_loop = LoopKind::None;
    std::uint8_t m_buttons = 0;
};

}  // namespace colonosim::procedure
