// Trainer rates report: the procedure screen's frame rate and the physics
// loop's rate over a whole procedure, not only its first seconds. The
// procedure screen of the first task, in a 1400x900 window, runs the autopilot
// (the scripted expert) on the default colon for `--seconds` of simulated
// time, as a student's session does; every `--window` seconds of wall time the
// report prints the frames drawn and the loop steps taken per wall-clock
// second, with the simulated time and insertion they were taken at and the
// scale the endoscope view draws at (RenderScaleGovernor). The last line gives
// the medians of the windows from `--from` seconds simulated on. The session
// itself is the same every run (a fixed patient and a fixed-step loop); only
// how fast it goes differs. The loop falls behind real time where a step
// takes longer than a millisecond (deeper than the sigmoid).
// Run it under Xvfb with the software rasteriser, as the GUI test runs:
//
//   xvfb-run -a -s "-screen 0 1600x1000x24" build/bench/trainer_rates [--seconds 30] [--window 5] [--from 15]
//
// About a minute of wall time for each 15 s simulated past the sigmoid.

#include "ListArgument.h"

#include "db/Database.h"
#include "db/Records.h"
#include "trainer_ui/app/AppContext.h"
#include "trainer_ui/app/CurriculumMap.h"
#include "trainer_ui/app/EndoscopeViewWidget.h"
#include "trainer_ui/app/ProcedureScene.h"
#include "trainer_ui/app/ProcedureScreen.h"
#include "trainer_ui/app/TrainerApp.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

using namespace colonosim;

namespace {

struct Options {
    double seconds = 30.0;  ///< s simulated
    double window = 5.0;    ///< s of wall time a line
    double from = 15.0;     ///< s simulated: the summary's windows start there or later
};

Options parse(int argc, char** argv)
{
    Options options;
    bench::forEachOption(argc, argv, [&options](const std::string& flag, const std::string& text) {
        if (flag == "--seconds") {
            options.seconds = bench::parseNumber(flag, text, 1.0, 600.0);
        } else if (flag == "--window") {
            options.window = bench::parseNumber(flag, text, 0.5, 60.0);
        } else if (flag == "--from") {
            options.from = bench::parseNumber(flag, text, 0.0, 600.0);
        } else {
            throw std::invalid_argument(flag + ": unknown option (expected --seconds, --window or --from)");
        }
    });
    return options;
}

/// Processes events until `condition()` holds; false after `ms` without it.
template <class Condition>
bool waitFor(Condition condition, int ms)
{
    QElapsedTimer waited;
    waited.start();
    while (!condition() && waited.elapsed() < ms) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(1);
    }
    return condition();
}

double median(std::vector<double> values)
{
    if (values.empty()) {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int run(const Options& options)
{
    QTemporaryDir dir;
    db::Database database(dir.filePath(QStringLiteral("records.sqlite")).toStdString());
    db::Records records(database);
    const db::Actor admin = cli::seedFirstStart(records, "admin", "admin-password-1");
    records.addUser(admin, "ada", db::Role::Student, "ada-password-1");
    const db::Actor ada = records.authenticate("ada", "ada-password-1");
    app::AppContext context{database, records, ada, dir.path().toStdString()};
    const curricula::Curriculum curriculum = app::loadCurriculum(context);
    const curricula::Task* task = curriculum.find("navigation-straight");
    if (task == nullptr) {
        throw std::runtime_error("the curriculum has no task navigation-straight");
    }
    app::ProcedureOptions procedureOptions;
    procedureOptions.driver = app::Driver::Autopilot;
    procedureOptions.timeLimit = options.seconds;
    app::ProcedureScreen screen(context, *task, app::buildScene(std::nullopt), std::nullopt,
                                procedureOptions);
    screen.resize(1400, 900);
    screen.show();
    auto* view = screen.findChild<app::EndoscopeViewWidget*>(QStringLiteral("endoscopeView"));
    if (view == nullptr) {
        throw std::runtime_error("the procedure screen has no endoscope view");
    }
    if (!waitFor([&] { return screen.framesDrawn() > 0; }, 180000)) {
        throw std::runtime_error("the procedure screen drew no frame within 180 s");
    }

    std::printf("%-16s %-18s %12s %14s %12s\n", "simulated (s)", "insertion (mm)", "frames/s", "steps/s",
                "view scale");
    const auto windowMs = static_cast<int>(options.window * 1000.0);
    std::vector<double> frameRates;
    std::vector<double> stepRates;
    while (screen.shownTime() < options.seconds - 0.05) {
        QElapsedTimer wall;
        wall.start();
        const long frames0 = screen.framesDrawn();
        const double time0 = screen.shownTime();
        const double insertion0 = screen.shownInsertion();
        waitFor([] { return false; }, windowMs);
        const double seconds = static_cast<double>(wall.elapsed()) / 1000.0;
        const double time1 = screen.shownTime();
        const double frames = static_cast<double>(screen.framesDrawn() - frames0) / seconds;
        const double steps = 1e3 * (time1 - time0) / seconds;
        // A window in which the session ended ran part of its time without it.
        const bool ended = time1 >= options.seconds - 0.05 || time1 == time0;
        std::printf("%5.1f - %-8.1f %5.0f - %-10.0f %12.1f %14.0f %12.2f%s\n", time0, time1, 1e3 * insertion0,
                    1e3 * screen.shownInsertion(), frames, steps, view->renderScale(),
                    ended ? "  (ended)" : "");
        std::fflush(stdout);
        if (time0 >= options.from && !ended) {
            frameRates.push_back(frames);
            stepRates.push_back(steps);
        }
        if (time1 == time0) {
            break;  // the loop stopped (ended or failed)
        }
    }
    std::printf("from %.0f s simulated on, medians of %zu windows: %.1f frames/s, %.0f steps/s\n",
                options.from, frameRates.size(), median(frameRates), median(stepRates));
    screen.endAndStore();
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        const Options options = parse(argc, argv);
        app::useOpenGl33Core();
        QApplication qt(argc, argv);
        return run(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "trainer_rates: %s\n", error.what());
        return 2;
    }
}
