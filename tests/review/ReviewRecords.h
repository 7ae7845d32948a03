#pragma once
// The records the review screens are tested on, built once per test binary
// through Records as the trainer would: an administrator, an instructor of
// cohort "A", students ada and bob in "A", a benchmark set derived from
// expert runs, and completed sessions of short real procedures (expert and
// novice operators, 1-2 s simulated on the default colon) scored by the same
// code as `colonosim run --user`.
#include "db/Database.h"
#include "db/Records.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace colonosim::test {

struct ReviewRecords {
    std::filesystem::path dir;
    std::unique_ptr<db::Database> database;
    std::unique_ptr<db::Records> records;
    db::Actor admin, teacher, ada, bob;
    std::vector<qint64> adaSessions, bobSessions;

    static ReviewRecords& instance();
    ~ReviewRecords();

private:
    ReviewRecords();
};

inline constexpr const char* kTeacherPassword = "teacher-password";

}  // namespace colonosim::test
