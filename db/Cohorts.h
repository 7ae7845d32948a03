#pragma once
/// \file
/// Cohorts with their members and instructors, as each role may see them:
/// an administrator every cohort, an instructor the cohorts they are assigned
/// to, a student the cohorts they belong to. (Cohorts are created and filled
/// through Records.)

#include "db/Records.h"

#include <string>
#include <vector>

namespace colonosim::db {

struct CohortRow {
    qint64 id;
    std::string name;
    std::vector<std::string> members;      ///< by name
    std::vector<std::string> instructors;  ///< by name
};

/// Ordered by name; members and instructors by name.
[[nodiscard]] std::vector<CohortRow> readableCohorts(Database& database, const Actor& actor);

}  // namespace colonosim::db
