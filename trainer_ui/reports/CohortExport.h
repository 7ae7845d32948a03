#pragma once
/// \file
/// The reports of many trainees at once (a cohort), meant to run off the UI
/// thread:
///   Pdf   a folder with one signed certification report per trainee
///         (TRAINEE.pdf)
///   Csv   one file, every trainee's sessions
///   Xapi  one file, every trainee's statements in one array
/// Everything is written under a temporary name and renamed into place only
/// when complete: a cancelled or failed export leaves nothing at `out`.
/// Cancellation is checked between trainees.

#include "db/Database.h"
#include "db/Records.h"
#include "trainer_ui/reports/TraineeReport.h"

#include <filesystem>
#include <functional>
#include <stop_token>
#include <string>
#include <vector>

namespace colonosim::reports {

enum class ExportOutcome { Written, Cancelled };

/// `progress(done, total)` after each trainee (called on the exporting thread).
/// Throws what traineeReport() throws, and std::runtime_error naming `out`
/// when it exists already or cannot be written; nothing is left at `out` then.
ExportOutcome exportCohort(ReportFormat format, db::Database& database, db::Records& records,
                           const db::Actor& actor, const std::vector<std::string>& trainees,
                           const std::filesystem::path& out, std::stop_token stop,
                           const std::function<void(int, int)>& progress = {});

}  // namespace colonosim::reports
