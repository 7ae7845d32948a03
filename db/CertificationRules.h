#pragma once
/// \file
/// The certification rule sets of record (schema migration 5): each import
/// is a new version holding the rule-set XML exactly as imported; one
/// version is active, and certification status is always evaluated against
/// it. The shipped core rule set is version 1. Authorization, enforced here:
///   import, activate   administrators only (AccessDenied otherwise)
///   list, active       every role: whoever may read certification status
///                      reads the rules it is judged by
/// Imports are validated by curricula::parseRuleSet (the rule file's schema:
/// kinds, declared metrics, ranges), and the file's `version` attribute is
/// the version of record: it must be above every stored version. Every
/// import and activation is written to the audit log by the schema's triggers.

#include "curricula/Certification.h"
#include "db/Records.h"

#include <string>
#include <vector>

namespace colonosim::db {

struct RuleSetVersion {
    qint64 id;
    std::string name;
    int version;
    std::string importedBy;  ///< empty: shipped with colonosim
    std::string importedAt;
    bool active;
};

struct ActiveRuleSet {
    RuleSetVersion stored;
    curricula::RuleSet rules;
};

/// An import refused for its content: the errors name the file's line and
/// field, the value and what is allowed.
class RuleSetRejected : public DatabaseError {
public:
    RuleSetRejected(const std::string& message, std::vector<std::string> errors)
        : DatabaseError(message), m_errors(std::move(errors))
    {}
    [[nodiscard]] const std::vector<std::string>& errors() const { return m_errors; }

private:
    std::vector<std::string> m_errors;
};

class CertificationRules {
public:
    explicit CertificationRules(Database& database) : m_database(database) {}

    /// Validates and stores `xml` (from the file `label`) as a new, inactive
    /// version; returns it. RuleSetRejected when it does not validate or its
    /// version is not above the stored ones.
    RuleSetVersion import(const Actor& actor, const std::string& xml, const std::string& label);
    /// Makes `version` the active one; DatabaseError when no such version exists.
    void activate(const Actor& actor, int version);
    /// Every stored version, oldest first.
    [[nodiscard]] std::vector<RuleSetVersion> versions(const Actor& actor);
    /// The active version, parsed.
    [[nodiscard]] ActiveRuleSet active(const Actor& actor);
    /// The stored XML of `version`, exactly as imported.
    [[nodiscard]] std::string xml(const Actor& actor, int version);

private:
    Database& m_database;
};

}  // namespace colonosim::db
