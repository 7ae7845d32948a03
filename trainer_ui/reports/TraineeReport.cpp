#include "trainer_ui/reports/TraineeReport.h"

#include "trainer_ui/reports/CertificateSignature.h"
#include "trainer_ui/reports/PdfReport.h"
#include "trainer_ui/reports/ProgressReport.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace colonosim::reports {

std::string formatName(ReportFormat format)
{
    switch (format) {
    case ReportFormat::Pdf: return "pdf";
    case ReportFormat::Csv: return "csv";
    case ReportFormat::Xapi: return "xapi";
    }
    return "pdf";
}

std::optional<ReportFormat> parseFormat(const std::string& name)
{
    for (const ReportFormat f : {ReportFormat::Pdf, ReportFormat::Csv, ReportFormat::Xapi}) {
        if (formatName(f) == name) {
            return f;
        }
    }
    return std::nullopt;
}

std::string traineeReport(ReportFormat format, db::Database& database, db::Records& records,
                          const db::Actor& actor, const std::string& user, const std::string& xapiHome)
{
    const std::vector<db::SessionRow> sessions = records.sessions(actor, user);
    if (format == ReportFormat::Pdf && actor.role != db::Role::Administrator) {
        throw db::AccessDenied(actor.name + " (" + db::roleName(actor.role) +
                               ") may not issue certification reports: only administrators may");
    }
    switch (format) {
    case ReportFormat::Csv: return csvReport(sessions);
    case ReportFormat::Xapi: return xapiReport(sessions, xapiHome).dump(2) + "\n";
    case ReportFormat::Pdf: break;
    }
    const nlohmann::json progress =
        progressReport(sessions, user, db::CertificationRules(database).active(actor));
    const std::string pdf = pdfReport(sessions, progress, user, PdfIssue{actor.name, true});
    const SigningKey key = signingKey(database.path().string() + ".signing-key");
    const std::string sha = sha256Hex(pdf);
    const std::string signature = sign(key, signedMessage(user, sha));
    records.issueCertificate(actor, user, sha, signature, key.publicKeyHex);
    return pdf + trailerLine(user, key.publicKeyHex, signature);
}

std::string progressPdf(db::Database& database, db::Records& records, const db::Actor& actor,
                        const std::string& user)
{
    const std::vector<db::SessionRow> sessions = records.sessions(actor, user);
    return pdfReport(sessions, progressReport(sessions, user, db::CertificationRules(database).active(actor)),
                     user, PdfIssue{actor.name, false});
}

std::optional<std::string> readFileWhole(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeFileWhole(const std::filesystem::path& path, const std::string& bytes)
{
    std::filesystem::path partial = path;
    partial += ".partial";
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out << bytes;
        out.flush();
        if (!out) {
            const std::string why = std::strerror(errno);
            out.close();
            std::error_code ignored;
            std::filesystem::remove(partial, ignored);
            throw std::runtime_error(path.string() + " cannot be written: " + why);
        }
    }
    std::error_code error;
    std::filesystem::rename(partial, path, error);
    if (error) {
        std::filesystem::remove(partial, error);
        throw std::runtime_error(path.string() + " cannot be written: " + error.message());
    }
}

}  // namespace colonosim::reports
