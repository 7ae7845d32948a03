#pragma once
/// \file
/// What the record-keeping subcommands share: the Qt application object
/// QtSql needs, the database (default: a SQLite file under the user's data
/// directory, created and seeded on first start; `--db FILE` overrides),
/// authentication (`--as NAME` plus a password from the environment variable
/// COLONOSIM_PASSWORD or from `--password-file FILE`, never from an
/// argument), and scoring a session into the records.
///
/// First start: the core curriculum is stored and a first administrator
/// "admin" is created, with the password in COLONOSIM_ADMIN_PASSWORD if set,
/// else a random one printed once. There is no fixed default password.

#include "db/Records.h"
#include "scoring/SessionMetrics.h"
#include "trainer_ui/cli/CommandLine.h"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

namespace colonosim::cli {

/// Options every records subcommand accepts.
inline const std::vector<std::string> kRecordsOptions = {"--db", "--as", "--password-file"};

/// Creates the Qt application object once (a QGuiApplication on the offscreen
/// platform when `gui`, for drawing reports).
void ensureQtApplication(bool gui = false);

[[nodiscard]] std::filesystem::path defaultDatabasePath();
/// The records database a command names: `--db FILE`, else the default.
[[nodiscard]] std::filesystem::path databasePath(const CommandLine& line);

struct OpenRecords {
    std::unique_ptr<db::Database> database;
    std::unique_ptr<db::Records> records;
    /// The administrator created by this open (first start only).
    std::optional<db::Actor> firstAdministrator;
};

/// The name under which the core curriculum is stored.
inline constexpr const char* kCoreCurriculum = "colonoscopy-core";

/// First start of a database with no user: creates the first administrator
/// `administrator` with `password` and stores the core curriculum. Both the
/// command line and the trainer's first-start dialog seed through here.
db::Actor seedFirstStart(db::Records& records, const std::string& administrator, const std::string& password);

/// Opens `--db` or the default; on first start seeds it, writing the one-time
/// notice to `notices`.
[[nodiscard]] OpenRecords openRecords(const CommandLine& line, std::ostream& notices);
/// The records database that already exists (for reading only, e.g. to
/// verify a report against the database that issued it): never created or
/// seeded; throws UsageError naming the path when there is none.
[[nodiscard]] OpenRecords openExistingRecords(const CommandLine& line);

/// A secret from `fileOption` (first line of the file) or else `envVar`;
/// UsageError naming both when neither is given.
[[nodiscard]] std::string readSecret(const CommandLine& line, const std::string& fileOption,
                                     const char* envVar, const std::string& what);

/// Authenticates `name` (default: the value of --as).
[[nodiscard]] db::Actor authenticate(db::Records& records, const CommandLine& line, const std::string& name);

/// Scores `values` for `task` (benchmark set named by the task, latest
/// version), adds "benchmark_met", and computes the user's progress
/// including this session. Fills scores, benchmark id, curriculum and progress.
void scoreInto(db::Records& records, const db::Actor& actor, const std::string& task,
               const scoring::MetricValues& values, db::SessionResult& result);

}  // namespace colonosim::cli
