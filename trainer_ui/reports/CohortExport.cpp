#include "trainer_ui/reports/CohortExport.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <system_error>

namespace colonosim::reports {

namespace {

/// Removes the partial output unless released.
class PartialOutput {
public:
    explicit PartialOutput(std::filesystem::path path) : m_path(std::move(path)) {}
    ~PartialOutput()
    {
        if (!m_released) {
            std::error_code ignored;
            std::filesystem::remove_all(m_path, ignored);
        }
    }
    PartialOutput(const PartialOutput&) = delete;
    PartialOutput& operator=(const PartialOutput&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return m_path; }
    void moveTo(const std::filesystem::path& destination)
    {
        std::error_code error;
        std::filesystem::rename(m_path, destination, error);
        if (error) {
            throw std::runtime_error(destination.string() + " cannot be written: " + error.message());
        }
        m_released = true;
    }

private:
    std::filesystem::path m_path;
    bool m_released = false;
};

/// CSV rows of many trainees under the first trainee's header would lose
/// score columns the first lacks: one table from all sessions instead.
std::string cohortCsv(db::Records& records, const db::Actor& actor, const std::vector<std::string>& trainees,
                      std::stop_token stop, const std::function<void(int, int)>& progress, bool& cancelled)
{
    std::vector<db::SessionRow> all;
    for (size_t k = 0; k < trainees.size(); ++k) {
        if (stop.stop_requested()) {
            cancelled = true;
            return {};
        }
        auto sessions = records.sessions(actor, trainees[k]);
        all.insert(all.end(), sessions.begin(), sessions.end());
        if (progress) {
            progress(static_cast<int>(k + 1), static_cast<int>(trainees.size()));
        }
    }
    return csvReport(all);
}

}  // namespace

ExportOutcome exportCohort(ReportFormat format, db::Database& database, db::Records& records,
                           const db::Actor& actor, const std::vector<std::string>& trainees,
                           const std::filesystem::path& out, std::stop_token stop,
                           const std::function<void(int, int)>& progress)
{
    if (std::filesystem::exists(out)) {
        throw std::runtime_error(out.string() + " exists already: choose another name, nothing was replaced");
    }
    std::filesystem::path staging = out;
    staging += ".partial";
    PartialOutput partial(staging);
    const int total = static_cast<int>(trainees.size());
    bool cancelled = false;
    if (format == ReportFormat::Csv) {
        const std::string csv = cohortCsv(records, actor, trainees, stop, progress, cancelled);
        if (cancelled) {
            return ExportOutcome::Cancelled;
        }
        writeFileWhole(staging, csv);
    } else if (format == ReportFormat::Xapi) {
        nlohmann::json statements = nlohmann::json::array();
        for (int k = 0; k < total; ++k) {
            if (stop.stop_requested()) {
                return ExportOutcome::Cancelled;
            }
            for (auto& s : xapiReport(records.sessions(actor, trainees[static_cast<size_t>(k)]))) {
                statements.push_back(std::move(s));
            }
            if (progress) {
                progress(k + 1, total);
            }
        }
        writeFileWhole(staging, statements.dump(2) + "\n");
    } else {
        std::filesystem::create_directories(staging);
        for (int k = 0; k < total; ++k) {
            if (stop.stop_requested()) {
                return ExportOutcome::Cancelled;
            }
            const std::string& trainee = trainees[static_cast<size_t>(k)];
            writeFileWhole(staging / (trainee + ".pdf"),
                           traineeReport(ReportFormat::Pdf, database, records, actor, trainee));
            if (progress) {
                progress(k + 1, total);
            }
        }
    }
    if (stop.stop_requested()) {
        return ExportOutcome::Cancelled;
    }
    partial.moveTo(out);
    return ExportOutcome::Written;
}

}  // namespace colonosim::reports
