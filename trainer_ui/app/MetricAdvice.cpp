#include "trainer_ui/app/MetricAdvice.h"

#include <QObject>

#include <array>
#include <utility>

namespace colonosim::app {

QString adviceFor(std::string_view metric)
{
    static const std::array<std::pair<std::string_view, const char*>, 20> kAdvice = {{
        {"cecal_intubation", "Reach the cecum: keep the dark lumen centred with the dials and advance "
                             "steadily, reducing loops as "
                             "they form."},
        {"withdrawal_time",
         "Withdraw more slowly from the cecum (at least 6 minutes), looking behind every fold."},
        {"clear_view",
         "Keep the lumen in view: when the picture turns red, pull back a little and steer towards the dark "
         "lumen."},
        {"red_out_count",
         "Avoid pushing the lens into the wall: pull back and find the lumen before advancing."},
        {"loop_count", "Avoid forming loops: when the tip stops following the shaft, pull back with "
                       "clockwise torque instead "
                       "of pushing."},
        {"looped_time", "Reduce loops sooner: as soon as the tip stops moving with the shaft, withdraw with "
                        "clockwise torque."},
        {"loops_reduced",
         "Reduce every loop you form: withdraw with clockwise torque until the tip moves one to one with the "
         "shaft again."},
        {"loops_n", "Straighten the sigmoid: withdraw with clockwise torque before advancing further."},
        {"loops_alpha",
         "An alpha loop formed: withdraw with clockwise torque to straighten it before going on."},
        {"loops_reverse_alpha",
         "A reverse alpha loop formed: withdraw and torque to straighten the sigmoid."},
        {"loops_gamma",
         "A transverse loop formed: withdraw to straighten it; ask for abdominal pressure if needed."},
        {"loops_reverse_splenic",
         "A reverse splenic loop formed: withdraw and re-advance with the shaft straight."},
        {"max_handle_force", "Push more gently: keep the handle force under 15 N, and when resistance "
                             "builds, withdraw a little and "
                             "steer."},
        {"mean_handle_force",
         "Use less force overall: advance in small steps and let the lumen open with air."},
        {"max_handle_torque",
         "Twist the shaft less forcefully: small rotations with the dials do most steering."},
        {"mean_handle_torque",
         "Use less torque overall: steer with the dials rather than by twisting the shaft."},
        {"discomfort_peak",
         "Keep the patient comfortable: less force, fewer loops and no more air than needed."},
        {"perforation",
         "The wall was perforated: never push against fixed resistance with the tip against the wall."},
        {"lesions_missed", "Inspect the whole mucosa and press M to mark each lesion while it is in view."},
        {"tip_path_length",
         "Move more economically: steer deliberately towards the lumen rather than sweeping."},
    }};
    for (const auto& [name, advice] : kAdvice) {
        if (name == metric) {
            return QObject::tr(advice);
        }
    }
    if (metric == "max_insertion") {
        return QObject::tr(
            "Advance further: keep the lumen centred and reduce loops so the shaft can go deeper.");
    }
    return QObject::tr("Compare this with the benchmark and repeat the task, watching this measure.");
}

}  // namespace colonosim::app
