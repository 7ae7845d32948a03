// Construct validity report: the scripted expert and the scripted novice on
// the same generated patients, each for a set simulated time (or until it
// has finished), scored from its recording by the scoring library. Per run:
// the time to the cecum when it was reached, the furthest the tip got along
// the colon, the deepest insertion (a run that ends with the scope in to its
// working length has run out of scope, not stalled), the looped time and the loops formed (with the alpha
// loops among them), the peak handle force, and the steps with the tip more than a scope diameter into the
// wall, and the steps whose chain solve the scope's step guard refused (Colonoscope::step). Then, per metric,
// on how many patients the expert did better than the novice.
//
//   construct_validity [--seconds S] [--seeds 1,2,3,...] [--element-points 0|1]
//                      [--side-normals 0|1] [--pleat-search 0|1] [--sticking-friction 0|1]
//                      [--spin-friction 0|1] [--haustral-axial-ratio R] [--max-node-step M]
//                      [--expert-insert-speed V] [--novice-steering-gain G]
//                      [--require EXPR] [--until-cecum 0|1] [--who both|expert|novice]
//
// Seed 0 is the default colon; any other seed is a generated patient, drawn
// under --require (the case generator's expression, e.g. "redundant_sigmoid":
// the literature separates novices from experts on hard cases only). With
// --until-cecum 1 a run ends when the cecum is reached (the three measures
// are then those of the insertion). --who runs one operator only (no
// comparison is then printed). The
// five contact options (contact.elementPoints, contact.sideNormals,
// contact.pleatSearch, contact.stickingFriction, contact.spinFriction;
// each flag's default is the parameter's: off) and the
// wall's tissue.haustralAxialRatio (1 by default) and the scope's step guard
// (scope.maxNodeStep, m; 0.2 by default) apply to both
// operators' runs. Two what-if flags change one operator's style:
// --expert-insert-speed (m/s; 0.03 by default) and --novice-steering-gain
// (1/s; 0.5 by default, 0: the novice never turns the dials).

#include "bench/ListArgument.h"
#include "bench/PatientFromSeed.h"
#include "scoring/SessionMetrics.h"
#include "simcore/contact/ContactParameters.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/physics/TissueParameters.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"
#include "simcore/scope/ScopeParameters.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace colonosim;

struct Run {
    double timeToCecum = -1.0;  ///< s; -1 when not reached
    double furthest = 0.0;      ///< m along the colon
    double inserted = 0.0;      ///< the deepest insertion, m
    // Until the cecum (or the run's end), s: the scope fed in, drawn back, held still.
    double feeding = 0.0;
    double drawingBack = 0.0;
    double holding = 0.0;
    double colonLength = 0.0;  ///< m
    double loopedTime = 0.0;   ///< s
    double loops = 0.0;
    double alphaLoops = 0.0;
    double peakForce = 0.0;     ///< N
    long outside = 0;           ///< steps with the tip more than a scope diameter into the wall
    long shaftOutside = 0;      ///< steps with a contact point behind the tip more than a scope diameter in
    double deepestShaft = 0.0;  ///< the deepest contact point behind the tip, m into the wall
    long guarded = 0;           ///< steps with a chain solve refused by the step guard
};

/// The model options both operators run with (ContactParameters.h,
/// TissueParameters.h).
struct ModelOptions {
    double elementPoints = contact::ContactParameters{}.elementPoints;
    double sideNormals = contact::ContactParameters{}.sideNormals;
    double pleatSearch = contact::ContactParameters{}.pleatSearch;
    double stickingFriction = contact::ContactParameters{}.stickingFriction;
    double spinFriction = contact::ContactParameters{}.spinFriction;
    double haustralAxialRatio = physics::TissueParameters{}.haustralAxialRatio;
    double maxNodeStep = scope::ScopeParameters{}.maxNodeStep;  ///< m
    cases::Constraints constraints;                             ///< what a generated patient must have
    bool untilCecum = false;                                    ///< end a run at the cecum
};

/// Which operators run on each patient.
struct Who {
    bool expert = true;
    bool novice = true;
};

Run runOperator(std::uint64_t seed, const procedure::OperatorStyle& style, double seconds,
                const ModelOptions& options)
{
    const bench::Patient patient = bench::patientFromSeed(seed, options.constraints);
    procedure::ProcedureSettings settings = patient.settings;
    settings.contact.elementPoints = options.elementPoints;
    settings.contact.sideNormals = options.sideNormals;
    settings.contact.pleatSearch = options.pleatSearch;
    settings.contact.stickingFriction = options.stickingFriction;
    settings.contact.spinFriction = options.spinFriction;
    settings.tissue.haustralAxialRatio = options.haustralAxialRatio;
    settings.scope.maxNodeStep = options.maxNodeStep;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(patient.anatomy);
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator driver(style);
    Run run;
    run.colonLength = anatomy.centreline.length();
    const auto steps = static_cast<long>(seconds / settings.stepping.loopStep);
    double lastInsertion = 0.0;
    for (long s = 0; s < steps && !driver.finished() && !(options.untilCecum && loop.cecumReached()); ++s) {
        loop.step(driver.next(loop));
        const auto& contacts = loop.lumen().contacts();
        run.outside += contacts.back().depth > settings.scope.outerDiameter ? 1 : 0;
        double shaftDepth = 0.0;
        for (std::size_t i = 0; i + 1 < contacts.size(); ++i) {
            shaftDepth = std::max(shaftDepth, contacts[i].depth);
        }
        run.shaftOutside += shaftDepth > settings.scope.outerDiameter ? 1 : 0;
        run.deepestShaft = std::max(run.deepestShaft, shaftDepth);
        run.guarded += loop.scope().guardRetries() > 0 ? 1 : 0;
        run.furthest = std::max(run.furthest, loop.lastFrame().tipArcLength);
        const double insertion = loop.lastFrame().input.insertion;
        run.inserted = std::max(run.inserted, insertion);
        if (!loop.cecumReached()) {
            const double dt = settings.stepping.loopStep;
            (insertion > lastInsertion   ? run.feeding
             : insertion < lastInsertion ? run.drawingBack
                                         : run.holding) += dt;
        }
        lastInsertion = insertion;
    }
    scoring::ScoringContext context;
    context.colonLength = run.colonLength;
    context.excessiveForce = settings.recorder.excessiveForce;
    context.lesionsPresent = static_cast<int>(settings.lesions.size());
    const scoring::MetricValues metrics = scoring::computeMetrics(loop.recording(), context);
    const auto value = [&metrics](const char* name) {
        const auto it = metrics.find(name);
        return it == metrics.end() ? -1.0 : it->second;
    };
    run.timeToCecum = value("time_to_cecum");
    run.loopedTime = value("looped_time");
    run.loops = value("loop_count");
    run.alphaLoops = value("loops_alpha");
    run.peakForce = value("max_handle_force");
    return run;
}

void printRun(const char* who, std::uint64_t seed, const Run& r)
{
    const std::string cecum = r.timeToCecum >= 0.0 ? bench::shortest(r.timeToCecum) : "-";
    std::printf(
        "%-7s %-6llu %10s %8.3f / %-6.3f %10.3f %9.1f %6.0f %6.0f %10.2f %9ld %9ld %12.1f %9ld %8.1f %8.1f "
        "%8.1f\n",
        who, static_cast<unsigned long long>(seed), cecum.c_str(), r.furthest, r.colonLength, r.inserted,
        r.loopedTime, r.loops, r.alphaLoops, r.peakForce, r.outside, r.shaftOutside, r.deepestShaft * 1e3,
        r.guarded, r.feeding, r.drawingBack, r.holding);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv)
{
    double seconds = 60.0;
    std::vector<std::uint64_t> seeds{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    ModelOptions options;
    Who who;
    // The operators' styles; two what-if flags change them (the defaults are
    // expertStyle() and noviceStyle()).
    procedure::OperatorStyle expertStyle = procedure::expertStyle();
    procedure::OperatorStyle noviceStyle = procedure::noviceStyle();
    try {
        bench::forEachOption(argc, argv, [&](const std::string& flag, const std::string& value) {
            if (flag == "--seconds") {
                seconds = bench::parseList(flag, value, 0.001, 3600.0).front();
            } else if (flag == "--seeds") {
                seeds = bench::parseSeeds(flag, value);
            } else if (flag == "--element-points") {
                const auto& spec = contact::ContactParameters::elementPointsSpec;
                options.elementPoints = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--side-normals") {
                const auto& spec = contact::ContactParameters::sideNormalsSpec;
                options.sideNormals = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--pleat-search") {
                const auto& spec = contact::ContactParameters::pleatSearchSpec;
                options.pleatSearch = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--sticking-friction") {
                const auto& spec = contact::ContactParameters::stickingFrictionSpec;
                options.stickingFriction =
                    bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--spin-friction") {
                const auto& spec = contact::ContactParameters::spinFrictionSpec;
                options.spinFriction = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--haustral-axial-ratio") {
                const auto& spec = physics::TissueParameters::haustralAxialSpec;
                options.haustralAxialRatio =
                    bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--max-node-step") {
                const auto& spec = scope::ScopeParameters::maxNodeStepSpec;
                options.maxNodeStep = bench::parseList(flag, value, spec.minValue, spec.maxValue).front();
            } else if (flag == "--expert-insert-speed") {
                // Up to the fastest insertion the contact is tested at (issue: 0.5 m/s).
                expertStyle.insertSpeed = bench::parseList(flag, value, 0.001, 0.5).front();
            } else if (flag == "--novice-steering-gain") {
                noviceStyle.steeringGain = bench::parseList(flag, value, 0.0, 100.0).front();
            } else if (flag == "--require") {
                options.constraints.require = cases::RequireExpression::parse(value);
            } else if (flag == "--who") {
                if (value != "both" && value != "expert" && value != "novice") {
                    throw std::invalid_argument("--who: value '" + value +
                                                "' is not one of both, expert, novice");
                }
                who.expert = value != "novice";
                who.novice = value != "expert";
            } else if (flag == "--until-cecum") {
                if (value != "0" && value != "1") {
                    throw std::invalid_argument("--until-cecum: value '" + value + "' is not 0 or 1");
                }
                options.untilCecum = value == "1";
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --seconds, --seeds, --element-points, "
                                            "--side-normals, --pleat-search, --sticking-friction, "
                                            "--spin-friction, --haustral-axial-ratio, --max-node-step, "
                                            "--expert-insert-speed, --novice-steering-gain, "
                                            "--require, --until-cecum, --who)");
            }
        });
    } catch (const std::exception& error) {
        std::fprintf(stderr, "construct_validity: %s\n", error.what());
        return 2;
    }
    std::printf(
        "expert and novice, %.1f s per run; cecum: time to cecum (s, - when not reached); furthest: "
        "tip along the colon / colon length (m); inserted: the deepest insertion (m; the operators keep "
        "5 cm of the scope's working length outside); outside: steps with the tip more than a scope "
        "diameter into the wall; shaft_out: steps with a contact point behind the tip more than a scope "
        "diameter into the wall, shaft_deep_mm the deepest; guarded: steps with a chain solve refused by the "
        "scope's step guard; "
        "feed, back, hold: time until the cecum (or the run's end) with the scope fed in, drawn back, "
        "held still (s); "
        "contact options: elementPoints %g, sideNormals %g, pleatSearch %g, stickingFriction %g, "
        "spinFriction %g; "
        "tissue.haustralAxialRatio %g; scope.maxNodeStep %g m; the expert feeds at %g m/s, the novice "
        "steers at %g 1/s; patients: %s; %s\n",
        seconds, options.elementPoints, options.sideNormals, options.pleatSearch, options.stickingFriction,
        options.spinFriction, options.haustralAxialRatio, options.maxNodeStep, expertStyle.insertSpeed,
        noviceStyle.steeringGain, options.constraints.empty() ? "any" : options.constraints.text().c_str(),
        options.untilCecum ? "runs end at the cecum" : "runs go on past the cecum");
    std::printf("%-7s %-6s %10s %17s %10s %9s %6s %6s %10s %9s %9s %12s %9s %8s %8s %8s\n", "who", "seed",
                "cecum_s", "furthest_m", "inserted_m", "looped_s", "loops", "alpha", "peak_F_N", "outside",
                "shaft_out", "shaft_deep_mm", "guarded", "feed_s", "back_s", "hold_s");
    const bool compare = who.expert && who.novice;
    int fasterToCecum = 0;
    int lessLooped = 0;
    int lessForce = 0;
    for (const std::uint64_t seed : seeds) {
        Run expert;
        Run novice;
        if (who.expert) {
            expert = runOperator(seed, expertStyle, seconds, options);
            printRun("expert", seed, expert);
        }
        if (who.novice) {
            novice = runOperator(seed, noviceStyle, seconds, options);
            printRun("novice", seed, novice);
        }
        if (!compare) {
            continue;
        }
        // Faster to the cecum: the expert reached it, and the novice did not or later.
        const bool expertFaster = expert.timeToCecum >= 0.0 &&
                                  (novice.timeToCecum < 0.0 || expert.timeToCecum < novice.timeToCecum);
        fasterToCecum += expertFaster ? 1 : 0;
        lessLooped += expert.loopedTime < novice.loopedTime ? 1 : 0;
        lessForce += expert.peakForce < novice.peakForce ? 1 : 0;
    }
    if (!compare) {
        return 0;
    }
    const auto n = static_cast<int>(seeds.size());
    std::printf(
        "patients where the expert did better: reached the cecum faster %d of %d, less looped time %d of %d, "
        "lower peak handle force %d of %d\n",
        fasterToCecum, n, lessLooped, n, lessForce, n);
    return 0;
}
