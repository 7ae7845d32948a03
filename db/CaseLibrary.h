#pragma once
/// \file
/// The case library: stored cases (Records::storeCase) and their assignment
/// to trainees or whole cohorts. Authorization, enforced here:
///   list cases    instructors and administrators see every stored case; a
///                 student sees the cases assigned to them (directly or
///                 through a cohort)
///   assign        administrators to anyone; an instructor to a student of
///                 their cohorts, or to a cohort they are assigned to;
///                 students never
///   assignments   of a trainee: whoever may read that trainee's records
/// Refusals throw AccessDenied naming the actor, their role, the operation
/// and the rule; every assignment is audited.

#include "db/Records.h"

#include <string>
#include <vector>

namespace colonosim::db {

struct CaseRow {
    qint64 id;
    std::string name;
};

struct AssignmentRow {
    qint64 id;
    qint64 caseId;
    std::string caseName;
    std::string cohort;  ///< empty when assigned to the trainee directly
    std::string assignedBy, assignedAt;
};

class CaseLibrary {
public:
    explicit CaseLibrary(Database& database) : m_database(database) {}

    [[nodiscard]] std::vector<CaseRow> cases(const Actor& actor);
    /// The case XML; DatabaseError when it does not exist, AccessDenied for a
    /// student it is not assigned to.
    [[nodiscard]] std::string caseXml(const Actor& actor, qint64 caseId);

    qint64 assignToTrainee(const Actor& actor, qint64 caseId, const std::string& trainee);
    qint64 assignToCohort(const Actor& actor, qint64 caseId, const std::string& cohort);
    /// What `trainee` is assigned, directly and through their cohorts, oldest first.
    [[nodiscard]] std::vector<AssignmentRow> assignments(const Actor& actor, const std::string& trainee);

private:
    [[nodiscard]] bool assignedTo(qint64 caseId, qint64 user);
    [[nodiscard]] bool teaches(qint64 instructor, qint64 student);
    void requireCase(qint64 caseId);

    Database& m_database;
};

}  // namespace colonosim::db
