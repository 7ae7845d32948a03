#pragma once
/// \file
/// Metrics of one session, computed from its procedure Recording (samples at
/// 100 Hz and edge events). Definitions: MetricDefinitions.cpp.
///   time to cecum      first CecumReached event (absent when never reached)
///   withdrawal time    end of session - time to cecum; effective: less the
///                      union of red-out (RedOutStart/End) and cleaning
///                      (CleaningStart/End: water or suction held) after the
///                      cecum, each overlap counted once; an interval still
///                      open at the end is closed at the end
///   clear view         1 - (red-out time / total time), red-out from RedOutStart/End
///   mucosa visualised  the renderer's coverage (ScoringContext::mucosaSeen)
///                      when it watched the session; else a geometric
///                      estimate: the colon is cut into bins along its length;
///                      a bin counts as seen when a sample with a clear view has
///                      the shaft's insertion depth in it. Insertion stands in
///                      for the tip's arc length, so a looped shaft overstates it.
///   loops              LoopFormed / LoopResolved events; looped time from samples
///   forces             |handle force|, |handle torque| over the samples; time with
///                      |handle force| above the excessive threshold
///   discomfort         peak, and share of samples >= the moderate threshold
///   lesions            detected: distinct lesions a LesionMarked event found in
///                      view. When the renderer watched the session (its
///                      LesionOnScreen / LesionOffScreen events are in the
///                      recording), in view means on screen, a fold in front
///                      hiding it, within sightingTolerance of the mark; else
///                      the loop's signal, which the mark names (LesionInView,
///                      no occlusion test). missed: present - detected; time
///                      to detection: mean of (mark - first in view of that
///                      lesion) over the detected; false marks: marks that
///                      found no lesion in view
///   path length        sum of |tip(k+1) - tip(k)|
///   insertion efficiency  max insertion / sum of positive insertion steps

#include "simcore/params/Parameter.h"
#include "simcore/procedure/Recorder.h"

#include <map>
#include <optional>
#include <string>

namespace colonosim::scoring {

using MetricValues = std::map<std::string, double>;

struct ScoringContext {
    static constexpr params::ParameterSpec moderateDiscomfortSpec{
        "moderateDiscomfort",
        "1",
        6.0,
        0.0,
        10.0,
        "discomfort (0-10) counted as moderate or worse",
        "JAG comfort: moderate-severe is > 3 on a 5-point scale, i.e. above 6 on 0-10"};
    static constexpr params::ParameterSpec mucosaBinSpec{
        "mucosaBin",
        "m",
        0.01,
        0.001,
        0.1,
        "length of a colon bin of the geometric mucosa estimate",
        "model choice: 1 cm, about a third of the field of view at working distance"};
    static constexpr params::ParameterSpec sightingToleranceSpec{
        "sightingTolerance",
        "s",
        0.1,
        0.0,
        1.0,
        "a mark finds a lesion the renderer showed this close in time to it",
        "model choice: one coverage update (RenderParameters::coverageInterval, 10 Hz), the "
        "renderer's own time resolution"};
    static constexpr params::ParameterSpec colonLengthSpec{
        "colonLength",
        "m",
        1.66,
        0.5,
        3.0,
        "the case's colon, centreline length (ProcedureLoop::colonLength)",
        "generous bounds about adult colons of 110-196 cm at CT colonography (Utano et al. 2021; "
        "Khashab et al. 2009: 189.5 +/- 26.3 cm)"};
    double colonLength = colonLengthSpec.defaultValue;  ///< m, from the anatomy
    double excessiveForce = procedure::RecorderParameters::excessiveForceSpec.defaultValue;  ///< N
    double moderateDiscomfort = moderateDiscomfortSpec.defaultValue;
    double mucosaBin = mucosaBinSpec.defaultValue;                  ///< m
    double sightingTolerance = sightingToleranceSpec.defaultValue;  ///< s
    int lesionsPresent = 0;
    /// Seen wall area over the whole wall's (0-1), from the renderer's
    /// coverage of the session (cli::SessionCoverage); none: the geometric
    /// estimate from the recording. It gives % mucosa visualised, and
    /// mucosa_from_renderer says which it was.
    std::optional<double> mucosaSeen;
};

/// All declared metrics except time_to_cecum when the cecum was not reached.
[[nodiscard]] MetricValues computeMetrics(const procedure::Recording& recording,
                                          const ScoringContext& context);

/// The context a session was scored in, read back from its stored metrics
/// for re-scoring from its recording: lesions present, the colon's length,
/// and the renderer's coverage when it measured it (the recording does not
/// carry the wall's shape, so that figure stands). Metrics stored before a
/// figure was kept leave its default.
[[nodiscard]] ScoringContext storedContext(const MetricValues& stored);

}  // namespace colonosim::scoring
