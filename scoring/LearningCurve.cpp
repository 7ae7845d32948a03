#include "scoring/LearningCurve.h"

#include <algorithm>
#include <cmath>

namespace colonosim::scoring {

void CusumParameters::validate() const
{
    params::require("cusum", acceptableSpec, acceptable);
    params::require("cusum", unacceptableSpec, unacceptable);
    params::require("cusum", alphaSpec, alpha);
    params::require("cusum", betaSpec, beta);
    if (unacceptable <= acceptable) {
        throw params::ParameterError(
            "cusum.unacceptableFailureRate = " + std::to_string(unacceptable) +
            " must exceed cusum.acceptableFailureRate = " + std::to_string(acceptable));
    }
}

double CusumParameters::s() const
{
    const double P = std::log(unacceptable / acceptable);
    const double Q = std::log((1.0 - acceptable) / (1.0 - unacceptable));
    return Q / (P + Q);
}

double CusumParameters::upperLimit() const
{
    const double PQ =
        std::log(unacceptable / acceptable) + std::log((1.0 - acceptable) / (1.0 - unacceptable));
    return std::log((1.0 - beta) / alpha) / PQ;
}

double CusumParameters::lowerLimit() const
{
    const double PQ =
        std::log(unacceptable / acceptable) + std::log((1.0 - acceptable) / (1.0 - unacceptable));
    return -std::log((1.0 - alpha) / beta) / PQ;
}

double CusumParameters::lcLimit() const
{
    return std::log((1.0 - beta) / alpha);
}

LearningCurve learningCurve(const std::vector<bool>& failures, const CusumParameters& parameters)
{
    parameters.validate();
    const double s = parameters.s();
    const double h1 = parameters.upperLimit();
    const double h = parameters.lcLimit();
    const double success = std::log((1.0 - parameters.acceptable) / (1.0 - parameters.unacceptable));
    const double failure = std::log(parameters.acceptable / parameters.unacceptable);
    LearningCurve curve;
    double c = 0.0, lc = 0.0;
    for (size_t n = 0; n < failures.size(); ++n) {
        c += (failures[n] ? 1.0 : 0.0) - s;
        lc = std::max(0.0, lc + (failures[n] ? failure : success));
        curve.cusum.push_back(c);
        curve.lcCusum.push_back(lc);
        if (curve.unacceptableAt == 0 && c >= h1) {
            curve.unacceptableAt = static_cast<int>(n) + 1;
        }
        if (curve.competentAt == 0 && lc >= h) {
            curve.competentAt = static_cast<int>(n) + 1;
        }
    }
    return curve;
}

}  // namespace colonosim::scoring
