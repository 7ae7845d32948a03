#include "scoring/MetricDefinitions.h"

#include <array>

namespace colonosim::scoring {

namespace {
constexpr std::string_view kMentor =
    "GI Mentor II validation studies (Phitayakorn et al. 2009; Fayez et al. 2010)";
constexpr std::string_view kQuality = "ASGE/ACG quality indicators; ESGE 2017; UK bowel cancer screening";
constexpr std::string_view kForce = "Colonoscopy Force Monitor study; Endo TS-1; Appleyard et al. 2000";
constexpr std::string_view kDops = "JAG colonoscopy DOPS; GAGES-C";

constexpr std::array kDefinitions = {
    MetricDefinition{"time_to_cecum", "Time to cecum", "s", Better::Lower,
                     "from insertion to the cecum; absent when not reached", kMentor},
    MetricDefinition{"cecal_intubation", "Cecal intubation", "1", Better::Higher,
                     "1 when the cecum was reached, else 0", kQuality},
    MetricDefinition{"total_time", "Total time", "s", Better::Neither, "length of the session", kMentor},
    MetricDefinition{"withdrawal_time", "Withdrawal time", "s", Better::Higher,
                     "from the cecum to the end of the session", kQuality},
    MetricDefinition{
        "effective_withdrawal_time", "Effective withdrawal time", "s", Better::Higher,
        "withdrawal time less red-out (wall contact) and cleaning (water or suction held) time, overlaps "
        "counted once",
        "withdrawal quality studies"},
    MetricDefinition{
        "mucosa_visualised", "Mucosa visualised", "1", Better::Higher,
        "share of the wall area seen: inside the lens's view, within working distance, at a sufficient "
        "angle and not occluded (the renderer's coverage, 10 Hz); where the renderer cannot run, the share "
        "of the colon length passed by the tip with a clear view (geometric estimate)",
        kMentor},
    MetricDefinition{
        "mucosa_from_renderer", "Mucosa measured by the renderer", "1", Better::Neither,
        "1 when mucosa_visualised came from the renderer's coverage, 0 from the geometric estimate",
        "model choice: says how the figure beside it was obtained"},
    MetricDefinition{"clear_view", "Clear view", "1", Better::Higher, "share of the time without red-out",
                     kMentor},
    MetricDefinition{"red_out_count", "Red-outs", "1", Better::Lower, "red-outs (lens against the wall)",
                     "JAG DOPS: tip control avoids red-outs"},
    MetricDefinition{"loop_count", "Loops formed", "1", Better::Lower, "loops formed", kMentor},
    MetricDefinition{"looped_time", "Time with a loop", "s", Better::Lower, "time with a loop in the shaft",
                     kMentor},
    MetricDefinition{"loops_reduced", "Loops reduced", "1", Better::Higher,
                     "loops formed that were resolved again", "JAG DOPS: loop management"},
    MetricDefinition{"loops_n", "N loops", "1", Better::Lower, "sigmoid N-loops",
                     "loop types, clinical-assessment.md"},
    MetricDefinition{"loops_alpha", "Alpha loops", "1", Better::Lower, "alpha loops",
                     "loop types, clinical-assessment.md"},
    MetricDefinition{"loops_reverse_alpha", "Reverse alpha loops", "1", Better::Lower, "reverse alpha loops",
                     "loop types, clinical-assessment.md"},
    MetricDefinition{"loops_gamma", "Gamma (deep transverse) loops", "1", Better::Lower,
                     "gamma and deep transverse loops", "loop types, clinical-assessment.md"},
    MetricDefinition{"loops_reverse_splenic", "Reverse splenic loops", "1", Better::Lower,
                     "reverse splenic flexure loops", "loop types, clinical-assessment.md"},
    MetricDefinition{"max_handle_force", "Peak handle force", "N", Better::Lower,
                     "largest axial handle force (magnitude)", kForce},
    MetricDefinition{"mean_handle_force", "Mean handle force", "N", Better::Lower,
                     "mean axial handle force (magnitude)", kForce},
    MetricDefinition{"max_handle_torque", "Peak handle torque", "N m", Better::Lower,
                     "largest handle torque (magnitude)", kForce},
    MetricDefinition{"mean_handle_torque", "Mean handle torque", "N m", Better::Lower,
                     "mean handle torque (magnitude)", kForce},
    MetricDefinition{"excessive_force_time", "Time above the force limit", "s", Better::Lower,
                     "time with the handle force above the recorder's excessive-force threshold", kForce},
    MetricDefinition{"discomfort_peak", "Peak discomfort", "1", Better::Lower, "peak discomfort, 0-10",
                     "GI Mentor II; Endo TS-1"},
    MetricDefinition{"discomfort_moderate_share", "Time at moderate discomfort or worse", "1", Better::Lower,
                     "share of the time at moderate or worse discomfort", "JAG comfort indicator"},
    MetricDefinition{"perforation", "Perforation", "1", Better::Lower, "1 when the wall was perforated",
                     "UK screening"},
    MetricDefinition{"lesions_present", "Lesions present", "1", Better::Neither, "lesions in the case",
                     kMentor},
    MetricDefinition{"lesions_detected", "Lesions detected", "1", Better::Higher,
                     "lesions marked while in view (each counted once)", kMentor},
    MetricDefinition{"lesions_missed", "Lesions missed", "1", Better::Lower,
                     "lesions present less lesions detected", kMentor},
    MetricDefinition{"time_to_detection", "Time to detection", "s", Better::Lower,
                     "mean time from a detected lesion's first coming into view to its mark", kMentor},
    MetricDefinition{"false_lesion_marks", "False lesion marks", "1", Better::Lower,
                     "marks made with no lesion in view", kMentor},
    MetricDefinition{"colon_length", "Colon length", "m", Better::Neither,
                     "the case's colon, centreline length (the geometric mucosa estimate's bins span it; "
                     "re-scoring reads it back)",
                     "model choice: a property of the case, kept with the session's figures"},
    MetricDefinition{
        "lesions_from_renderer", "Lesions judged by the renderer", "1", Better::Neither,
        "1 when a lesion counted as in view only where the renderer showed it (a fold in front hides "
        "it), 0 by the loop's own signal (no occlusion test)",
        "model choice: says how the lesion figures beside it were obtained"},
    MetricDefinition{"tip_path_length", "Tip path length", "m", Better::Lower,
                     "distance travelled by the tip", kMentor},
    MetricDefinition{"insertion_efficiency", "Insertion efficiency", "1", Better::Higher,
                     "deepest insertion over the total forward shaft travel (1: never backed off)",
                     "GI Mentor II efficiency"},
    MetricDefinition{"max_insertion", "Deepest insertion", "m", Better::Higher,
                     "deepest insertion of the shaft", kDops},
};
}  // namespace

std::span<const MetricDefinition> metricDefinitions()
{
    return kDefinitions;
}

const MetricDefinition* findMetric(std::string_view name)
{
    for (const MetricDefinition& d : kDefinitions) {
        if (d.name == name) {
            return &d;
        }
    }
    return nullptr;
}

}  // namespace colonosim::scoring
