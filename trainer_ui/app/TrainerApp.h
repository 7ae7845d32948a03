#pragma once
/// \file
/// `colonosim` with no subcommand on a machine with a display, or
/// `colonosim gui [--db FILE]` / `colonosim --db FILE`: the trainer window.
/// It makes the QApplication (OpenGL 3.3 core as the default surface format,
/// before any window exists), opens the records (default: the SQLite file in
/// the user's data directory), runs the first start when the records are new
/// (the password from COLONOSIM_ADMIN_PASSWORD when set, else chosen in a
/// dialog), and shows the login.

#include <span>

namespace colonosim::app {

/// True when a window can be shown: DISPLAY, WAYLAND_DISPLAY or QT_QPA_PLATFORM is set.
[[nodiscard]] bool displayAvailable();

/// Sets the default surface format the views need (OpenGL 3.3 core); call before the QApplication exists.
void useOpenGl33Core();

/// Runs the trainer until its window closes; returns the exit status.
int runTrainer(std::span<char* const> args);

}  // namespace colonosim::app
