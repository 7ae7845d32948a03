// Contact stability report: the scripted expert on several patients, for
// several values of contact.loadRelaxation, and how often its tip moved
// faster than 2 m/s (a step longer than 2 mm) or lay more than a scope
// diameter into the wall. The figures behind the parameter's default.
//
//   contact_stability [--seconds S] [--seeds 0,1,2,3] [--relaxation 1,0.5,0.3]
//
// Seed 0 is the default colon; any other seed is a generated patient.

#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace colonosim;

constexpr double kFastStep = 2e-3;  ///< m of tip motion in one 1 ms step: faster than 2 m/s

struct Outcome {
    long fastSteps = 0;   ///< steps with the tip moving more than kFastStep
    long outside = 0;     ///< steps with the tip more than a scope diameter into the wall
    double deepest = 0;   ///< m
    double furthest = 0;  ///< m along the colon
};

Outcome runExpert(std::uint64_t seed, double relaxation, double seconds)
{
    procedure::ProcedureSettings settings;
    geometry::AnatomyParameters anatomyParameters;
    if (seed != 0) {
        const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(seed));
        anatomyParameters = scene.anatomy;
        settings = cases::procedureSettings(scene);
    }
    settings.contact.loadRelaxation = relaxation;
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(anatomyParameters);
    procedure::ProcedureLoop loop(anatomy, settings);
    procedure::ScriptedOperator expert(procedure::expertStyle());
    Outcome outcome;
    Eigen::Vector3d previous = loop.scope().tipPose().position;
    const auto steps = static_cast<long>(seconds / settings.stepping.loopStep);
    for (long s = 0; s < steps && !expert.finished(); ++s) {
        loop.step(expert.next(loop));
        const Eigen::Vector3d tip = loop.scope().tipPose().position;
        const double depth = loop.lumen().contacts().back().depth;
        outcome.fastSteps += (tip - previous).norm() > kFastStep ? 1 : 0;
        outcome.outside += depth > settings.scope.outerDiameter ? 1 : 0;
        outcome.deepest = std::max(outcome.deepest, depth);
        outcome.furthest = std::max(outcome.furthest, loop.lastFrame().tipArcLength);
        previous = tip;
    }
    return outcome;
}

std::string shortest(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

std::vector<double> parseList(const std::string& flag, const std::string& text, double low, double high)
{
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || item.empty() || !(value >= low && value <= high)) {
            throw std::invalid_argument(flag + ": value '" + item + "' is not a number in [" + shortest(low) +
                                        ", " + shortest(high) + "]");
        }
        values.push_back(value);
    }
    if (values.empty()) {
        throw std::invalid_argument(flag + ": no values given");
    }
    return values;
}

}  // namespace

int main(int argc, char** argv)
{
    double seconds = 50.0;
    std::vector<double> seeds{0, 1, 2, 3};
    std::vector<double> relaxations{1.0, 0.5, 0.3};
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string flag = argv[i];
            if (i + 1 >= argc) {
                throw std::invalid_argument(flag + ": a value is needed");
            }
            const std::string value = argv[++i];
            if (flag == "--seconds") {
                seconds = parseList(flag, value, 0.001, 3600.0).front();
            } else if (flag == "--seeds") {
                seeds = parseList(flag, value, 0.0, 1e9);
            } else if (flag == "--relaxation") {
                relaxations = parseList(flag, value, 0.05, 1.0);
            } else {
                throw std::invalid_argument("unknown option '" + flag +
                                            "' (allowed: --seconds, --seeds, --relaxation)");
            }
        }
        for (const double seed : seeds) {
            if (seed != static_cast<double>(static_cast<std::uint64_t>(seed))) {
                throw std::invalid_argument("--seeds: value " + shortest(seed) +
                                            " is not a whole number in [0, 1e+09]");
            }
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "contact_stability: %s\n", error.what());
        return 2;
    }
    std::printf("expert, %.1f s per run; fast: tip steps longer than 2 mm; outside: steps with the tip more "
                "than a scope diameter into the wall\n",
                seconds);
    std::printf("%-10s %-6s %10s %10s %12s %12s\n", "relaxation", "seed", "fast", "outside", "deepest_mm",
                "furthest_m");
    for (const double relaxation : relaxations) {
        Outcome total;
        for (const double seed : seeds) {
            const Outcome o = runExpert(static_cast<std::uint64_t>(seed), relaxation, seconds);
            std::printf("%-10.2f %-6.0f %10ld %10ld %12.1f %12.3f\n", relaxation, seed, o.fastSteps,
                        o.outside, o.deepest * 1e3, o.furthest);
            std::fflush(stdout);
            total.fastSteps += o.fastSteps;
            total.outside += o.outside;
            total.deepest = std::max(total.deepest, o.deepest);
        }
        std::printf("%-10.2f %-6s %10ld %10ld %12.1f\n", relaxation, "all", total.fastSteps, total.outside,
                    total.deepest * 1e3);
    }
    return 0;
}
