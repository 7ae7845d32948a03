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
///   mucosa visualised  GEOMETRIC ESTIMATE (the renderer does not yet report
///                      coverage): the colon is cut into bins along its length;
///                      a bin counts as seen when a sample with a clear view has
///                      the shaft's insertion depth in it. Insertion stands in
///                      for the tip's arc length, so a looped shaft overstates it.
///   loops              LoopFormed / LoopResolved events; looped time from samples
///   forces             |handle force|, |handle torque| over the samples; time with
///                      |handle force| above the excessive threshold
///   discomfort         peak, and share of samples >= the moderate threshold
///   lesions            detected: distinct lesions named by a LesionMarked event
///                      (the recorder names the lesion in view when marked);
///                      missed: present - detected; time to detection: mean of
///                      (mark - first LesionInView of that lesion) over the
///                      detected; false marks: marks with no lesion in view
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
    double colonLength = 1.66;  ///< m, from the anatomy
    double excessiveForce = procedure::RecorderParameters::excessiveForceSpec.defaultValue;  ///< N
    double moderateDiscomfort = moderateDiscomfortSpec.defaultValue;
    double mucosaBin = mucosaBinSpec.defaultValue;  ///< m
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

}  // namespace colonosim::scoring
