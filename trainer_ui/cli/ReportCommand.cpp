/// \file
/// `colonosim report --user NAME --format pdf|csv|xapi --out FILE [--as NAME]`
/// and `colonosim report verify FILE`.
///   pdf   the certification report (administrators): trainee, sessions, the
///         learning curves drawn with QPainter (composite score per session;
///         CUSUM and LC-CUSUM of cecal intubation) and the certification rules;
///         signed with Ed25519 and recorded in the certificates table
///         (reports/CertificateSignature.h); built by reports/TraineeReport.h
///   csv   every metric and score of every completed session, one row each
///   xapi  one xAPI statement per completed session (actor, verb "completed",
///         object the curriculum task, result with score, success, completion,
///         duration and our metrics as extensions), as a JSON array
/// verify: valid when the signature checks against the content and the
/// database holds the same record (hash, signature, public key, trainee).

#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/RecordsAccess.h"
#include "trainer_ui/reports/CertificateSignature.h"
#include "trainer_ui/reports/TraineeReport.h"

#include <fstream>
#include <iostream>

namespace colonosim::cli {

namespace {

std::string readFile(const std::string& path)
{
    std::optional<std::string> bytes = reports::readFileWhole(path);
    if (!bytes) {
        throw UsageError(path + ": cannot be read");
    }
    return std::move(*bytes);
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) {
        throw UsageError("--out = " + path + ": cannot be written");
    }
}

int verify(const CommandLine& line, const std::string& file)
{
    const std::string bytes = readFile(file);
    const auto trailer = reports::splitTrailer(bytes);
    if (!trailer) {
        std::cout << "invalid: " << file << " carries no colonosim signature\n";
        return 1;
    }
    const std::string sha = reports::sha256Hex(trailer->content);
    if (!reports::verifySignature(trailer->publicKey, trailer->signature,
                                  reports::signedMessage(trailer->user, sha))) {
        std::cout << "invalid: the signature does not match the content (the file was changed)\n";
        return 1;
    }
    OpenRecords open = openExistingRecords(line);
    const auto record = open.records->certificateBySha(sha);
    if (!record || record->signature != trailer->signature || record->publicKey != trailer->publicKey ||
        record->user != trailer->user) {
        std::cout << "invalid: the records hold no matching certificate for this file\n";
        return 1;
    }
    std::cout << "valid: certification report of " << record->user << ", issued by " << record->issuedBy
              << " on " << record->issuedAt << " (certificate " << record->id << ")\n";
    return 0;
}

}  // namespace

int runReport(std::span<char* const> args)
{
    std::vector<std::string> options = {"--user", "--format", "--out", "--xapi-home"};
    options.insert(options.end(), kRecordsOptions.begin(), kRecordsOptions.end());
    const CommandLine line(args, {"--help"}, options);
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim report --user NAME --format pdf|csv|xapi --out FILE [--as NAME] [--db "
               "FILE]\n"
               "       colonosim report verify FILE [--db FILE]\n"
               "pdf: the signed certification report (administrators); csv: every metric of every\n"
               "session; xapi: xAPI statements (JSON; --xapi-home IRI: the organisation's IRI root for\n"
               "accounts, activities and extensions). verify exits 0 when valid, 1 when invalid.\n";
        return 0;
    }
    ensureQtApplication(true);
    if (!line.positional().empty()) {
        if (line.positional()[0] != "verify" || line.positional().size() != 2) {
            throw UsageError("expected: report verify FILE (got \"" + line.positional()[0] + "\")");
        }
        return verify(line, line.positional()[1]);
    }
    const auto user = line.value("--user");
    const auto format = line.value("--format");
    const auto out = line.value("--out");
    if (!user || !format || !out) {
        throw UsageError("--user, --format and --out are required (see --help)");
    }
    if (*format != "pdf" && *format != "csv" && *format != "xapi") {
        throw UsageError("--format = " + *format + " is not one of pdf, csv, xapi");
    }
    OpenRecords open = openRecords(line, std::cerr);
    const db::Actor actor = authenticate(*open.records, line, line.value("--as").value_or(*user));
    const std::string home = line.value("--xapi-home").value_or(reports::kXapiHome);
    if (*format == "xapi" && home.rfind("https://", 0) != 0 && home.rfind("http://", 0) != 0) {
        throw UsageError("--xapi-home = " + home + " is not an http(s) IRI");
    }
    try {
        writeFile(*out, reports::traineeReport(*reports::parseFormat(*format), *open.database, *open.records,
                                               actor, *user, home));
    } catch (const db::AccessDenied& error) {
        throw UsageError(std::string("refused: ") + error.what());
    }
    std::cout << "written: " << *out << '\n';
    return 0;
}

}  // namespace colonosim::cli
