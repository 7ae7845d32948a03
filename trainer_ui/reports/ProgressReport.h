#pragma once
/// \file
/// A trainee's standing in the core curriculum, as JSON: task states under
/// proficiency-based progression, the CUSUM and LC-CUSUM learning curve of
/// cecal intubation (failure = cecum not reached) with its decision limits,
/// and the certification rules met and not met under the active rule set of
/// record (db/CertificationRules.h), named with its version. Read through
/// Records, so a student sees only themselves, an instructor the students of
/// their cohorts.

#include "db/CertificationRules.h"
#include "db/Records.h"

#include <nlohmann/json.hpp>

#include <string>

namespace colonosim::reports {

/// Throws db::AccessDenied when `actor` may not read `user`'s records.
[[nodiscard]] nlohmann::json progressReport(db::Database& database, db::Records& records,
                                            const db::Actor& actor, const std::string& user);
/// The same from the trainee's completed sessions already read (Records::sessions)
/// and the active rule set already read (CertificationRules::active).
[[nodiscard]] nlohmann::json progressReport(const std::vector<db::SessionRow>& sessions,
                                            const std::string& user, const db::ActiveRuleSet& rules);

/// A certification rule's observed value as a person reads it: "none yet"
/// when nothing has been observed (NaN), else the number to 3 significant digits.
[[nodiscard]] std::string observedText(double observed);
/// The sessions a certification rule of the report looked at, as a person
/// reads them: "2", or "2 of the 10 it needs" while its window of last
/// sessions is not yet filled (the rule cannot be met before).
[[nodiscard]] std::string sessionsText(const nlohmann::json& rule);

/// "NAME, version N": the rule set a progressReport() was judged by.
[[nodiscard]] std::string ruleSetLabel(const nlohmann::json& progress);

}  // namespace colonosim::reports
