#pragma once
/// \file
/// The trainee's report as PDF (QPdfWriter, QPainter; a QGuiApplication must
/// exist): trainee, sessions, the learning curves (composite score per
/// session; CUSUM and LC-CUSUM of cecal intubation with their decision
/// limits) and the certification rules. A certification report is then
/// signed (CertificationReport.h); a progress report is the same pages,
/// marked as not a certificate.

#include "db/Records.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace colonosim::reports {

struct PdfIssue {
    std::string issuer;       ///< who issues it (a user name)
    bool certificate = true;  ///< certification report (signed afterwards) or progress report
};

/// `progress`: progressReport() of the same trainee.
[[nodiscard]] std::string pdfReport(const std::vector<db::SessionRow>& sessions,
                                    const nlohmann::json& progress, const std::string& user,
                                    const PdfIssue& issue);

}  // namespace colonosim::reports
