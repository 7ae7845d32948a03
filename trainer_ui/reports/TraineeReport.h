#pragma once
/// \file
/// One trainee's report in one format, built the same way wherever it is
/// asked for (the `report` subcommand, the headless demonstration, the
/// administrator's screen):
///   Pdf   the certification report: administrators only; drawn, signed with
///         Ed25519 (the key next to the database, CertificateSignature.h) and
///         recorded in the certificates table, the signature trailer appended
///   Csv   every metric and score of every completed session
///   Xapi  xAPI statements of every completed session
/// and files written whole or not at all.

#include "db/Database.h"
#include "db/Records.h"
#include "trainer_ui/reports/SessionReports.h"

#include <filesystem>
#include <optional>
#include <string>

namespace colonosim::reports {

enum class ReportFormat { Pdf, Csv, Xapi };
[[nodiscard]] std::string formatName(ReportFormat format);  ///< "pdf", "csv", "xapi"
/// nullopt unless `name` is one of pdf, csv, xapi.
[[nodiscard]] std::optional<ReportFormat> parseFormat(const std::string& name);

/// The report's bytes. Throws db::AccessDenied when `actor` may not read the
/// trainee, or (Pdf) is not an administrator; std::runtime_error naming the
/// key file when it cannot be read or created.
[[nodiscard]] std::string traineeReport(ReportFormat format, db::Database& database, db::Records& records,
                                        const db::Actor& actor, const std::string& user,
                                        const std::string& xapiHome = kXapiHome);

/// The trainee's own progress report as PDF, unsigned and not recorded as a
/// certificate (anyone who may read the trainee's records).
[[nodiscard]] std::string progressPdf(db::Database& database, db::Records& records, const db::Actor& actor,
                                      const std::string& user);

/// Writes `bytes` to a temporary file beside `path` and renames it over
/// `path`, so a reader never sees half a file. Throws std::runtime_error
/// naming the file and the reason.
void writeFileWhole(const std::filesystem::path& path, const std::string& bytes);
/// The whole content of `path` (bytes as stored), or nothing when it cannot be read.
[[nodiscard]] std::optional<std::string> readFileWhole(const std::filesystem::path& path);

}  // namespace colonosim::reports
