/// \file
/// `colonosim`: with no arguments, the trainer window when a display exists
/// (else the headless demonstration); `colonosim gui [--db FILE]` or
/// `colonosim --db FILE` for the window; with a subcommand, a headless tool.
/// Exit status: 0 success, 1 failure of the run itself, 2 bad input.

#include "simcore/devices/Gamepad.h"
#include "simcore/geometry/MeshImport.h"
#include "simcore/params/Parameter.h"
#include "trainer_ui/app/TrainerApp.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"

#include <cstring>
#include <iostream>
#include <span>
#include <string>

namespace {
void printUsage()
{
    std::cout
        << "usage: colonosim [SUBCOMMAND] [OPTIONS]\n"
           "With no subcommand: the trainer window when a display exists (DISPLAY, WAYLAND_DISPLAY or\n"
           "QT_QPA_PLATFORM set), else the headless demonstration.\n"
           "Subcommands (each has --help):\n"
           "  gui         the trainer window: gui [--db FILE] (also: colonosim --db FILE)\n"
           "  demo        headless demonstration: generate a case, run the expert, score it into the\n"
           "              records, write the PDF report (demo --tissue: the tissue physics alone)\n"
           "  params      declared physical parameters with units, ranges and sources\n"
           "  mesh        import and check a patient-specific colon surface\n"
           "  bench       speed-versus-error report: bench [--quick] --out DIR\n"
           "  rod         cantilever equilibrium of the colonoscope's rod model, as JSON\n"
           "  run         one procedure: run --default --operator "
           "expert|novice|replay:TRACE|hdc:PORT|gamepad\n"
           "              --out DIR\n"
           "  case        patient cases: case generate|validate|stats (randomized from population "
           "statistics)\n"
           "  user        the records' users: user add|list|passwd (authenticate with --as NAME)\n"
           "  rules       the certification rule sets: rules list|import FILE|activate VERSION --as ADMIN\n"
           "  progress    a trainee's tasks, learning curve and certification rules: progress --user NAME\n"
           "  report      report --user NAME --format pdf|csv|xapi --out FILE; report verify FILE\n"
           "  backup      online backup of the records: backup --out FILE\n"
           "  benchmarks  benchmark sets from expert sessions: benchmarks derive|show --name SET\n"
           "  render      endoscope and scope-shape views as PNG: render --default|--case FILE --out "
           "view.png\n"
           "Records: run ... --user NAME [--db FILE] stores and scores a session.\n";
}
}  // namespace

int main(int argc, char** argv)
{
    using namespace colonosim;
    const std::span<char* const> all(argv, static_cast<size_t>(argc));
    const std::string first = argc > 1 ? argv[1] : "";
    // No subcommand: the window where one can be shown; options alone (--db FILE) mean the window too.
    const bool window = first == "gui" || first.starts_with("--db") || (argc == 1 && app::displayAvailable());
    const std::string command = window ? "gui" : (argc > 1 ? first : "demo");
    const bool named = argc > 1 && !first.starts_with("--db");  // a subcommand word comes first
    const std::span<char* const> rest = named ? all.subspan(2) : all.subspan(1);
    try {
        if (command == "gui") {
            return app::runTrainer(rest);
        }
        if (command == "--help" || command == "-h" || command == "help") {
            printUsage();
            return 0;
        }
        if (command == "demo") {
            return cli::runDemo(rest);
        }
        if (command == "params") {
            return cli::runParams(rest);
        }
        if (command == "mesh") {
            return cli::runMesh(rest);
        }
        if (command == "run") {
            return cli::runProcedure(rest);
        }
        if (command == "bench") {
            return cli::runBench(rest);
        }
        if (command == "rod") {
            return cli::runRod(rest);
        }
        if (command == "case") {
            return cli::runCase(rest);
        }
        if (command == "user") {
            return cli::runUser(rest);
        }
        if (command == "rules") {
            return cli::runRules(rest);
        }
        if (command == "progress") {
            return cli::runProgress(rest);
        }
        if (command == "report") {
            return cli::runReport(rest);
        }
        if (command == "backup") {
            return cli::runBackup(rest);
        }
        if (command == "benchmarks") {
            return cli::runBenchmarks(rest);
        }
        if (command == "render") {
            return cli::runRender(rest);
        }
        std::cerr << "colonosim: unknown subcommand \"" << command << "\" (see colonosim --help)\n";
        return 2;
    } catch (const cli::UsageError& error) {
        std::cerr << "colonosim " << command << ": " << error.what() << '\n';
        return 2;
    } catch (const devices::DeviceError& error) {
        std::cerr << "colonosim " << command << ": " << error.what() << '\n';
        return 2;
    } catch (const params::ParameterError& error) {
        std::cerr << "colonosim " << command << ": " << error.what() << '\n';
        return 2;
    } catch (const geometry::MeshImportError& error) {
        std::cerr << error.what() << '\n';
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "colonosim " << command << ": " << error.what() << '\n';
        return 1;
    }
}
