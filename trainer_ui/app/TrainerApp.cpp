#include "trainer_ui/app/TrainerApp.h"

#include "trainer_ui/app/FirstStartDialog.h"
#include "trainer_ui/app/MainWindow.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QApplication>
#include <QDir>
#include <QSurfaceFormat>

#include <cstdlib>
#include <iostream>

namespace colonosim::app {

bool displayAvailable()
{
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) {
        if (const char* value = std::getenv(name); value != nullptr && *value != '\0') {
            return true;
        }
    }
    return false;
}

void useOpenGl33Core()
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
}

int runTrainer(std::span<char* const> args)
{
    const cli::CommandLine line(args, {"--help"}, {"--db"});
    if (line.has("--help")) {
        std::cout << "usage: colonosim [gui] [--db FILE]\n"
                     "The trainer window (needs a display). --db FILE: the records database (default: "
                     "records.sqlite in the user's data directory).\n"
                     "On first start the administrator \"admin\" is created with the password in\n"
                     "COLONOSIM_ADMIN_PASSWORD, or one chosen in the first-start dialog.\n";
        return 0;
    }
    if (!displayAvailable()) {
        throw cli::UsageError(
            "the trainer window needs a display (DISPLAY, WAYLAND_DISPLAY or QT_QPA_PLATFORM "
            "set); without one, use the headless subcommands (colonosim --help)");
    }
    useOpenGl33Core();
    static int argc = 1;
    static char name[] = "colonosim";
    static char* argv[] = {name, nullptr};
    QApplication::setApplicationName(QStringLiteral("colonosim"));
    QApplication application(argc, argv);

    const std::filesystem::path path = cli::databasePath(line);
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path());
    }
    db::Database database(path);
    db::Records records(database);
    if (database.abortedOnOpen() > 0) {
        std::cerr << "records: " << database.abortedOnOpen()
                  << " interrupted session(s) marked aborted; they do not count\n";
    }
    if (records.empty()) {
        const char* chosen = std::getenv("COLONOSIM_ADMIN_PASSWORD");
        if (chosen != nullptr && *chosen != '\0') {
            (void)cli::seedFirstStart(records, FirstStartDialog::kAdministrator, chosen);
            std::cerr
                << "records: first start of " << path.string()
                << ": administrator \"admin\" created with the password from COLONOSIM_ADMIN_PASSWORD\n";
        } else {
            FirstStartDialog dialog(records, path);
            if (dialog.exec() != QDialog::Accepted) {
                std::cerr << "colonosim: no administrator was created, so the trainer closes; start it again "
                             "to choose the password\n";
                return 1;
            }
        }
    }
    MainWindow window(database, records, QDir::homePath().toStdString());
    window.show();
    return QApplication::exec();
}

}  // namespace colonosim::app
