#pragma once
/// \file
/// Certification rules (certification-rules.xml, schema/certification.xsd):
/// each rule has a kind, its numbers and a source, and is evaluated over a
/// trainee's completed sessions, oldest first. Kinds are described in the
/// rule file's header comment. Metric names must be declared scoring metrics.

#include "scoring/SessionMetrics.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace colonosim::curricula {

enum class RuleKind { CountAtLeast, ShareAtLeast, ShareBelow, MedianAtLeast, NoneInLast };

struct CertificationRule {
    std::string id, description, source;
    RuleKind kind = RuleKind::CountAtLeast;
    std::string metric, among;
    double atLeast = 1.0;
    int window = 0;  ///< last N sessions; 0: all
    double value = 0.0;
};

struct RuleSet {
    std::string name;
    int version = 1;
    std::vector<CertificationRule> rules;
};

struct RuleSetRead {
    std::optional<RuleSet> value;
    std::vector<std::string> errors;
    [[nodiscard]] bool ok() const { return value.has_value(); }
};

[[nodiscard]] RuleSetRead parseRuleSet(const std::string& xml, const std::string& label);
[[nodiscard]] const std::string& coreRuleSetXml();

struct RuleStatus {
    const CertificationRule* rule;
    bool met;
    double observed;  ///< the count, share or median found (NaN when there is nothing to measure)
    int sessions;     ///< sessions the rule looked at
};

[[nodiscard]] std::vector<RuleStatus> evaluate(const RuleSet& rules,
                                               const std::vector<scoring::MetricValues>& sessions);

}  // namespace colonosim::curricula
