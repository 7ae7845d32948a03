#pragma once
/// \file
/// Reports of completed sessions as data, for one trainee or many:
///   csv   every metric (SI, unit in the header) and every score of every
///         session, one row each
///   xapi  one xAPI statement per session (actor, verb "completed", object the
///         curriculum task, result with score, success, completion, duration
///         and our metrics as extensions), as a JSON array

#include "db/Records.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace colonosim::reports {

/// IRI root of our activities, accounts and extensions unless the
/// organisation names its own (the reserved .example domain: no one else's
/// IRIs are claimed).
inline constexpr const char* kXapiHome = "https://colonosim.example";

[[nodiscard]] std::string csvReport(const std::vector<db::SessionRow>& sessions);
[[nodiscard]] nlohmann::json xapiReport(const std::vector<db::SessionRow>& sessions,
                                        const std::string& home = kXapiHome);

}  // namespace colonosim::reports
