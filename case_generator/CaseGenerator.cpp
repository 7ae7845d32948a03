#include "case_generator/CaseGenerator.h"

#include "case_generator/AnatomySampler.h"
#include "case_generator/DifficultyEstimate.h"
#include "case_generator/EnvironmentSampler.h"
#include "case_generator/PathologySampler.h"
#include "case_generator/PatientSampler.h"
#include "case_generator/Quantity.h"
#include "case_generator/Random.h"

namespace colonosim::cases {

bool CaseGenerator::attempt(std::uint64_t seed, std::uint64_t attemptNumber, const Constraints& constraints,
                            Case& c) const
{
    const Statistics& stats = m_stats;
    const RequireExpression& require = constraints.require;
    Random random(seed, attemptNumber);
    if (!samplePatient(stats, constraints, random, c.patient)) {
        // BMI depends on sex only: a range it misses that often is as good as impossible.
        throw ImpossibleConstraints("impossible constraints: no BMI drawn in " +
                                    std::to_string(kBmiDrawBudget) + " draws met \"" + constraints.text() +
                                    "\"; such a BMI is rarer than 1 in " + std::to_string(kBmiDrawBudget));
    }
    if (!require.holdsAt(Stage::Patient, c, stats)) {
        return false;
    }
    c.indication = sampleIndication(stats, random);
    sampleHistory(stats, c.patient, random, c.history, c.adhesions);
    if (!require.holdsAt(Stage::History, c, stats)) {
        return false;
    }
    sampleAnatomy(stats, c.patient, random, c.anatomy);
    for (Adhesion& a : c.adhesions) {
        // sampleHistory stored the fraction along the segment.
        a.place.position = quantity::position.quantise(a.place.position *
                                                       c.anatomy.length[static_cast<int>(a.place.segment)]);
    }
    if (!require.holdsAt(Stage::Anatomy, c, stats)) {
        return false;
    }
    samplePathology(stats, random, c);
    tuneToPatient(stats, c);
    fitLesionsToLumen(c);
    c.task = trainingTask(c);
    if (!require.holdsAt(Stage::Pathology, c, stats)) {
        return false;
    }
    sampleEnvironment(stats, random, c.environment);
    if (!require.holdsAt(Stage::Environment, c, stats)) {
        return false;
    }
    c.difficulty = estimateDifficulty(c, stats);
    if ((constraints.difficultyMin && c.difficulty.level < *constraints.difficultyMin) ||
        (constraints.difficultyMax && c.difficulty.level > *constraints.difficultyMax)) {
        return false;
    }
    if (!require.holdsAt(Stage::Difficulty, c, stats)) {
        return false;
    }
    c.provenance = {kFormatVersion,    seed,          attemptNumber,
                    kGeneratorVersion, stats.version, constraints.text()};
    return true;
}

Case CaseGenerator::generate(std::uint64_t seed, const Constraints& constraints) const
{
    if (const std::optional<std::string> why = constraints.impossibility(m_stats)) {
        throw ImpossibleConstraints("impossible constraints: " + *why);
    }
    Case c;
    for (std::uint64_t k = 0; k < kAttemptBudget; ++k) {
        if (attempt(seed, k, constraints, c)) {
            return c;
        }
    }
    throw ImpossibleConstraints("impossible constraints: no case in " + std::to_string(kAttemptBudget) +
                                " attempts met \"" + constraints.text() +
                                "\"; they are impossible together or rarer than 1 case in " +
                                std::to_string(kAttemptBudget));
}

}  // namespace colonosim::cases
