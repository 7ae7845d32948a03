/// \file
/// `colonosim rod`: static equilibrium of a cantilever (clamped at the origin
/// along +x, SI units, dead loads in -y) by the chain solver or the Newton
/// reference, as JSON. See simcore/scope/Cantilever.h and
/// reference/physical-parameters.md for the analytic solutions to compare with.

#include "simcore/scope/Cantilever.h"
#include "simcore/scope/ChainSolver.h"
#include "simcore/scope/ReferenceSolver.h"
#include "simcore/scope/ScopeParameters.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>

namespace colonosim::cli {

int runRod(std::span<char* const> args)
{
    const CommandLine line(args, {"--json", "--help"},
                           {"--length", "--ei", "--gj", "--tip-load", "--distributed-load", "--end-moment",
                            "--elements", "--solver", "--iterations"});
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim rod --length L --ei EI [--gj GJ] [--tip-load P] [--distributed-load q]\n"
               "                     [--end-moment M] --elements N --solver chain|reference\n"
               "                     [--iterations K] --json\n"
               "Static equilibrium of a cantilever clamped at the origin along +x; SI units; dead loads\n"
               "in -y (q per metre); M bends the same way. Prints tip_x_m, tip_y_m, tip_angle_rad (below\n"
               "+x), iterations and time_us as JSON.\n";
        return 0;
    }
    if (!line.positional().empty()) {
        throw UsageError("rod takes no arguments, got " + line.positional().front());
    }
    using scope::ScopeParameters;
    const auto& eiSpec = ScopeParameters::flexuralRigiditySpec;
    const auto& gjSpec = ScopeParameters::torsionalRigiditySpec;
    const double length = line.number("--length", 1.0, 0.01, 10.0, "m");
    const double ei = line.number("--ei", eiSpec.defaultValue, 1e-6, 1e6, "N m^2");
    const double gj = line.number("--gj", gjSpec.defaultValue, 1e-6, 1e6, "N m^2");
    const double tipLoad = line.number("--tip-load", 0.0, -1e4, 1e4, "N");
    const double distributed = line.number("--distributed-load", 0.0, -1e4, 1e4, "N/m");
    const double endMoment = line.number("--end-moment", 0.0, -1e4, 1e4, "N m");
    const double elementCount = line.number("--elements", 79, 1, 5000, "1");
    const double iterationCount = line.number("--iterations", 50, 1, 1e6, "1");
    for (const auto& [name, value] :
         {std::pair{"--elements", elementCount}, {"--iterations", iterationCount}}) {
        if (value != std::floor(value)) {
            throw UsageError(std::string(name) + " = " + std::to_string(value) + " is not a whole number");
        }
    }
    const int elements = static_cast<int>(elementCount);
    const int iterations = static_cast<int>(iterationCount);
    const std::string solver = line.value("--solver").value_or("chain");
    if (solver != "chain" && solver != "reference") {
        throw UsageError("--solver = " + solver + " is not one of: chain, reference");
    }
    if (!line.has("--json")) {
        throw UsageError("rod needs --json (the only output format)");
    }
    scope::DiscreteRod rod =
        scope::makeCantilever(elements, length, ei, gj,
                              {.tipLoad = tipLoad, .distributedLoad = distributed, .endMoment = endMoment});
    const auto start = std::chrono::steady_clock::now();
    int used = iterations;
    bool converged = true;
    double residual = 0.0;
    if (solver == "chain") {
        residual = scope::solveChain(rod, iterations, ScopeParameters::relaxationSpec.defaultValue);
    } else {
        const scope::ReferenceResult result = scope::solveReference(rod);
        used = result.iterations;
        converged = result.converged;
        residual = result.gradientNorm;
    }
    const double micros =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    const nlohmann::json out{{"tip_x_m", rod.position.back().x()},
                             {"tip_y_m", rod.position.back().y()},
                             {"tip_angle_rad", scope::tipAngle(rod)},
                             {"iterations", used},
                             {"time_us", micros},
                             {"solver", solver},
                             {"elements", elements},
                             {"converged", converged},
                             {"residual", residual}};
    std::cout << out.dump() << '\n';
    if (!std::isfinite(rod.position.back().norm())) {
        std::cerr << "colonosim rod: the solution is not finite\n";
        return 1;
    }
    return 0;
}

}  // namespace colonosim::cli
