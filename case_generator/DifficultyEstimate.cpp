#include "case_generator/DifficultyEstimate.h"

#include "case_generator/Quantity.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace colonosim::cases {

namespace {
constexpr std::array<std::string_view, 12> kFactors{"redundant_sigmoid",
                                                    "redundant_transverse",
                                                    "female",
                                                    "female_bmi_below_22",
                                                    "hysterectomy",
                                                    "prior_abdominal_surgery",
                                                    "mobile_descending",
                                                    "severe_diverticulosis",
                                                    "boston_total_3_to_5",
                                                    "boston_total_0_to_2",
                                                    "flat_or_depressed_lesion",
                                                    "diminutive_lesion"};
}  // namespace

std::span<const std::string_view> knownDifficultyFactors()
{
    return kFactors;
}

bool difficultyFactorPresent(std::string_view name, const Case& c, const Statistics& stats)
{
    const bool female = c.patient.sex == Sex::Female;
    const int boston = c.environment.bostonTotal();
    if (name == "redundant_sigmoid") {
        return c.anatomy.length[static_cast<int>(Segment::Sigmoid)] >= stats.redundantSigmoid;
    }
    if (name == "redundant_transverse") {
        return c.anatomy.length[static_cast<int>(Segment::Transverse)] >= stats.redundantTransverse;
    }
    if (name == "female") {
        return female;
    }
    if (name == "female_bmi_below_22") {
        return female && c.patient.bmi < 22.0;
    }
    if (name == "hysterectomy") {
        return c.history.hysterectomy;
    }
    if (name == "prior_abdominal_surgery") {
        return c.history.priorAbdominalSurgery;
    }
    if (name == "mobile_descending") {
        return c.anatomy.descendingMobile;
    }
    if (name == "severe_diverticulosis") {
        return c.diverticula.size() > 10;
    }
    if (name == "boston_total_3_to_5") {
        return boston >= 3 && boston <= 5;
    }
    if (name == "boston_total_0_to_2") {
        return boston <= 2;
    }
    if (name == "flat_or_depressed_lesion") {
        return std::any_of(c.lesions.begin(), c.lesions.end(),
                           [](const Lesion& l) { return isFlatOrDepressed(l.paris); });
    }
    if (name == "diminutive_lesion") {
        return std::any_of(c.lesions.begin(), c.lesions.end(),
                           [](const Lesion& l) { return l.size <= 0.0055; });
    }
    return false;
}

Difficulty estimateDifficulty(const Case& c, const Statistics& stats)
{
    Difficulty d;
    double points = 0.0;
    for (const DifficultyRule& rule : stats.difficulty) {
        if (difficultyFactorPresent(rule.name, c, stats)) {
            d.factors.push_back({rule.name, quantity::difficultyPoints.quantise(rule.points)});
            points += d.factors.back().points;
        }
    }
    d.level = std::min(5, 1 + static_cast<int>(std::floor(points + 1e-9)));
    return d;
}

TrainingTask trainingTask(const Case& c)
{
    const bool resectable = std::any_of(c.lesions.begin(), c.lesions.end(), [](const Lesion& l) {
        return (isAdenoma(l.histology) || isSerrated(l.histology)) && l.size >= 0.0055 && l.size <= 0.0255 &&
               l.paris != Paris::IIc;
    });
    if (resectable) {
        return TrainingTask::Polypectomy;
    }
    return c.lesions.empty() ? TrainingTask::Intubation : TrainingTask::Detection;
}

}  // namespace colonosim::cases
