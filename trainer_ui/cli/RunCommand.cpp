/// \file
/// `colonosim run --default|--case FILE --operator expert|novice|replay:TRACE|hdc:PORT|gamepad --out DIR
/// [--json] [--max-time S]`: one procedure on the default colon, driven by a scripted operator, a recorded
/// input trace, a Haptic Device Controller (colonosim-hdc) connecting over OpenIGTLink on PORT, or a gamepad.
/// Writes DIR/session.trace (the input trace), DIR/samples.csv, DIR/events.csv and DIR/recording.txt (the
/// canonical recording: two runs are bit-identical when these files are equal), and prints a summary: time to
/// cecum, loops by type, peak handle force, peak discomfort, and the mucosa visualised (the
/// renderer's coverage of the wall, SessionCoverage).
/// With `--user NAME [--db FILE] [--task ID]` the session is also stored and scored in the records: inserted
/// as running before the first step, and completed in one transaction with its trace, recording, events,
/// metrics, scores and the user's progress (see RecordsAccess.h for authentication).

#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "scoring/SessionMetrics.h"
#include "simcore/devices/Gamepad.h"
#include "simcore/devices/HdcOperator.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/cli/CaseArgument.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/LoopPacer.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/cli/SessionCoverage.h"
#include "trainer_ui/cli/SessionStore.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

namespace colonosim::cli {

namespace {
nlohmann::json summarise(const procedure::Recording& recording, double duration)
{
    nlohmann::json out;
    out["duration_s"] = duration;
    out["time_to_cecum_s"] = nullptr;
    std::map<std::string, int> loops;
    for (const auto& e : recording.events) {
        if (e.kind == procedure::EventKind::CecumReached && out["time_to_cecum_s"].is_null()) {
            out["time_to_cecum_s"] = e.time;
        }
        if (e.kind == procedure::EventKind::LoopFormed) {
            ++loops[e.detail];
        }
    }
    double peakForce = 0.0;
    double peakDiscomfort = 0.0;
    double looped = 0.0;
    for (size_t k = 0; k < recording.samples.size(); ++k) {
        const auto& s = recording.samples[k];
        peakForce = std::max(peakForce, s.handleForce);
        peakDiscomfort = std::max(peakDiscomfort, s.discomfort);
        if (s.loop != procedure::LoopKind::None && k + 1 < recording.samples.size()) {
            looped += recording.samples[k + 1].time - s.time;
        }
    }
    out["loops_by_type"] = loops;
    out["looped_time_s"] = looped;
    out["peak_handle_force_N"] = peakForce;
    out["peak_discomfort"] = peakDiscomfort;
    out["events"] = recording.events.size();
    return out;
}

}  // namespace

int runProcedure(std::span<char* const> args)
{
    std::vector<std::string> options = {"--case", "--operator", "--out", "--max-time", "--user", "--task"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--default", "--json", "--help"}, options);
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim run --default|--case FILE --operator "
               "expert|novice|replay:TRACE|hdc:PORT|gamepad\n"
               "                     --out DIR [--json] [--max-time S]\n"
               "One procedure at 1 kHz; writes session.trace, samples.csv, events.csv, recording.txt to "
               "DIR.\n"
               "  --max-time S   stop after S simulated seconds, 1-3600 (default 900)\n"
               "  hdc:PORT       wait on PORT (1024-65535, loopback) for colonosim-hdc; the session runs\n"
               "                 whether or not a device is connected, holding the last input\n"
               "  gamepad        the first game controller SDL finds (left stick: insert and twist;\n"
               "                 right stick: dials; A air, B water, X suction, Y mark lesion)\n"
               "  --user NAME    store and score the session in the records as NAME (password from\n"
               "                 COLONOSIM_PASSWORD or --password-file FILE)\n"
               "  --db FILE      the records database (default: records.sqlite in the user's data "
               "directory)\n"
               "  --task ID      the curriculum task of the session (default navigation-straight)\n";
        return 0;
    }
    const std::optional<std::string> caseFile = line.value("--case");
    if (caseFile.has_value() == line.has("--default")) {
        throw UsageError("choose the colon: --default or --case FILE (one of them)");
    }
    const std::optional<std::string> operatorName = line.value("--operator");
    const std::optional<std::string> out = line.value("--out");
    if (!operatorName || !out) {
        throw UsageError("--operator and --out are required (see --help)");
    }
    const double maxTime = line.number("--max-time", 900.0, 1.0, 3600.0, "s");
    std::unique_ptr<procedure::Operator> driver;
    devices::HdcOperator* hdc = nullptr;
    if (operatorName->starts_with("hdc:")) {
        const std::string port = operatorName->substr(4);
        char* end = nullptr;
        const long value = std::strtol(port.c_str(), &end, 10);
        if (port.empty() || *end != '\0' || value < 1024 || value > 65535) {
            throw UsageError("--operator hdc:PORT: port = \"" + port + "\" is outside [1024, 65535]");
        }
        auto made =
            std::make_unique<devices::HdcOperator>(static_cast<int>(value), devices::HapticParameters{});
        hdc = made.get();
        driver = std::move(made);
    } else if (*operatorName == "gamepad") {
        driver = std::make_unique<devices::GamepadOperator>(0);
    } else {
        driver = procedure::makeOperator(*operatorName);
    }
    std::filesystem::create_directories(*out);
    const std::optional<std::string> user = line.value("--user");
    if (!user && (line.value("--db") || line.value("--task"))) {
        throw UsageError("--db and --task store a session: they need --user NAME");
    }
    const std::string task = checkTask(line.value("--task").value_or("navigation-straight"));

    // A generated case sets the anatomy, the wall, the environment and the
    // lesions' and adhesions' places (cases::procedureSettings).
    procedure::ProcedureSettings settings;
    geometry::AnatomyParameters anatomyParameters;
    int lesionsPresent = 0;
    if (caseFile) {
        const cases::Case theCase = readCaseArgument(*caseFile);
        lesionsPresent = static_cast<int>(theCase.lesions.size());
        const cases::SceneSpec scene = cases::toScene(theCase);
        anatomyParameters = scene.anatomy;
        settings = cases::procedureSettings(scene);
    }
    const geometry::ColonAnatomy anatomy = geometry::buildProceduralColon(anatomyParameters);
    procedure::ProcedureLoop loop(anatomy, settings);

    // The records: the session row exists (running) before the first step.
    OpenRecords records;
    db::Actor actor;
    qint64 session = 0;
    if (user) {
        records = openRecords(line, std::cerr);
        actor = authenticate(*records.records, line, *user);
        std::optional<qint64> caseId;
        if (caseFile) {
            std::ifstream in(*caseFile);
            std::stringstream xml;
            xml << in.rdbuf();
            caseId = records.records->storeCase(actor, std::filesystem::path(*caseFile).filename().string(),
                                                xml.str());
        }
        // Which device drives the session: the HDC's own device name is also in the
        // session's device_connected events.
        std::string device = "scripted:" + *operatorName;
        if (hdc != nullptr) {
            device = *operatorName;
        } else if (const auto* pad = dynamic_cast<const devices::GamepadOperator*>(driver.get())) {
            device = "gamepad:" + pad->name();
        } else if (operatorName->starts_with("replay:")) {
            device = "replay";
        }
        session = records.records->beginSession(actor, caseId, task, device);
    }
    const double loopStep = loop.trace().loopStep;
    const auto steps = static_cast<long>(maxTime / loopStep);
    // A person's gamepad is integrated per step: the loop keeps the wall
    // clock for it. The HDC keeps time itself (a step per device frame);
    // scripted and replayed input runs as fast as the loop can.
    const bool wallClock = *operatorName == "gamepad";
    // The renderer's coverage of the wall, 10 times a simulated second: % mucosa visualised.
    const std::unique_ptr<SessionCoverage> coverage = tryCoverage(anatomy, loop, std::cerr);
    // Paced as the trainer paces it (LoopPacer.h): a loop behind real time
    // does not make up more than a tenth of a second once its steps are cheap.
    const auto start = std::chrono::steady_clock::now();
    const auto sinceStart = [&start] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    LoopPacer pacer;
    pacer.restart(loop.time(), 0.0, 1.0);
    for (long s = 0; s < steps && !driver->finished(); ++s) {
        if (wallClock) {
            std::this_thread::sleep_until(
                start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(pacer.dueAt(loop.time(), loopStep, sinceStart()))));
        }
        if (hdc != nullptr) {
            hdc->recordConnection(loop);
        }
        loop.step(driver->next(loop), hdc);  // the HDC is answered as soon as the scope has its load
        if (coverage) {
            coverage->observe(loop);
        }
    }
    // The loop's recording with the renderer's lesion events (on / off screen) merged in.
    const procedure::Recording recording = recordingSeenBy(loop, coverage.get());
    const std::filesystem::path dir(*out);
    procedure::writeTrace(dir / "session.trace", loop.trace());
    recording.writeCsv(dir / "samples.csv", dir / "events.csv");
    std::ofstream(dir / "recording.txt") << recording.canonicalText();

    nlohmann::json summary = summarise(recording, loop.time());
    const std::optional<double> mucosaSeen =
        coverage ? std::optional<double>(coverage->finalFraction()) : std::nullopt;
    summary["mucosa_visualised"] = mucosaSeen ? nlohmann::json(*mucosaSeen) : nlohmann::json();
    if (coverage) {
        summary["coverage"] = {{"draws", coverage->draws()}, {"draw_seconds", coverage->drawSeconds()}};
        nlohmann::json bySegment = nlohmann::json::object();
        const auto fractions = coverage->finalBySegment();
        for (size_t k = 0; k < fractions.size(); ++k) {
            bySegment[std::string(geometry::segmentName(static_cast<geometry::Segment>(k)))] = fractions[k];
        }
        summary["mucosa_visualised_by_segment"] = bySegment;
    }
    std::string storedLine;
    if (user) {
        scoring::ScoringContext context;
        context.colonLength = loop.colonLength();
        context.lesionsPresent = lesionsPresent;
        context.mucosaSeen = mucosaSeen;
        const db::SessionResult result =
            completeStoredSession(*records.records, actor, session, task, loop, recording, context);
        summary["session"] = session;
        summary["task"] = task;
        summary["scores"] = result.scores;
        summary["task_state"] = result.progress.at(task);
        storedLine =
            std::string() + "stored: session " + std::to_string(session) + " of " + *user + ", task " + task +
            ", " +
            (result.scores.contains("composite")
                 ? "composite score " + std::to_string(result.scores.at("composite")) +
                       (result.scores.at("benchmark_met") > 0.5 ? " (benchmark met)" : " (benchmark not met)")
                 : std::string("not scored (no benchmark set stored for this task yet)")) +
            ", task now " + result.progress.at(task) +
            (result.progress.at(task) == "locked"
                 ? " (its prerequisites are not yet proficient: this attempt does not count)"
                 : "") +
            '\n';
    }
    if (line.has("--json")) {
        std::cout << summary.dump(2) << '\n';
    } else {
        // Rounded for a person to read (the --json summary keeps every digit).
        const auto fixed = [](double value, int digits) {
            std::ostringstream text;
            text << std::fixed << std::setprecision(digits) << value;
            return text.str();
        };
        std::cout << "procedure: " << fixed(loop.time(), 3) << " s simulated, operator " << *operatorName
                  << '\n'
                  << "time to cecum: "
                  << (summary["time_to_cecum_s"].is_null()
                          ? std::string("not reached")
                          : fixed(summary["time_to_cecum_s"].get<double>(), 2) + " s")
                  << '\n'
                  << "loops: " << summary["loops_by_type"].dump() << ", looped "
                  << fixed(summary["looped_time_s"].get<double>(), 2) << " s\n"
                  << "peak handle force: " << fixed(summary["peak_handle_force_N"].get<double>(), 1)
                  << " N; peak discomfort " << fixed(summary["peak_discomfort"].get<double>(), 1) << " / 10\n"
                  << "mucosa visualised: "
                  << (summary["mucosa_visualised"].is_null()
                          ? std::string("not measured (no renderer here)")
                          : fixed(100.0 * summary["mucosa_visualised"].get<double>(), 1) + "% of the wall")
                  << '\n'
                  << "written: " << (dir / "session.trace").string()
                  << ", samples.csv, events.csv, recording.txt\n"
                  << storedLine;
    }
    return 0;
}

}  // namespace colonosim::cli
