#pragma once
/// \file
/// Learning curves of binary outcomes per procedure (1 = failure, e.g. the
/// cecum not reached in the time limit, or a perforation).
///
/// CUSUM (Williams et al. 1992; as used in endoscopy training): with the
/// acceptable failure rate p0 and the unacceptable p1, type I and II errors
/// alpha and beta,
///   P = ln(p1/p0), Q = ln((1-p0)/(1-p1)), s = Q / (P + Q),
///   S_n = S_{n-1} + (x_n - s)         (a failure adds 1 - s, a success takes s),
///   h1 = ln((1-beta)/alpha) / (P + Q) (crossing upwards: unacceptable rate),
///   h0 = -ln((1-alpha)/beta) / (P + Q) (crossing downwards: acceptable rate).
/// LC-CUSUM (Biau et al. 2008): H0 "not yet competent" (failure rate p1)
/// against H1 "competent" (p0),
///   W_n = ln((1-p0)/(1-p1)) for a success, ln(p0/p1) for a failure,
///   S_n = max(0, S_{n-1} + W_n); competence is declared when S_n >= h,
///   here h = ln((1-beta)/alpha) (Wald's bound, a documented choice: Biau et
///   al. set h by simulation for their target power).
/// Defaults: p0 = 5%, p1 = 15% (the published parameterisation quoted in
/// clinical-assessment.md, Ward et al. Gut 2014 context), alpha 0.05, beta 0.20.

#include "simcore/params/Parameter.h"

#include <vector>

namespace colonosim::scoring {

struct CusumParameters {
    static constexpr params::ParameterSpec acceptableSpec{
        "acceptableFailureRate",
        "1",
        0.05,
        1e-4,
        0.5,
        "failure rate of a competent operator (p0)",
        "clinical-assessment.md: one published parameterisation uses 5% / 15%"};
    static constexpr params::ParameterSpec unacceptableSpec{
        "unacceptableFailureRate",
        "1",
        0.15,
        1e-4,
        0.9,
        "failure rate that is not acceptable (p1 > p0)",
        "clinical-assessment.md: one published parameterisation uses 5% / 15%"};
    static constexpr params::ParameterSpec alphaSpec{
        "alpha", "1", 0.05, 1e-4, 0.5, "type I error", "conventional choice"};
    static constexpr params::ParameterSpec betaSpec{
        "beta", "1", 0.20, 1e-4, 0.5, "type II error", "conventional choice (80% power)"};
    double acceptable = acceptableSpec.defaultValue;
    double unacceptable = unacceptableSpec.defaultValue;
    double alpha = alphaSpec.defaultValue;
    double beta = betaSpec.defaultValue;

    /// Throws ParameterError (also when p1 <= p0).
    void validate() const;
    [[nodiscard]] double s() const;
    [[nodiscard]] double upperLimit() const;  ///< h1
    [[nodiscard]] double lowerLimit() const;  ///< h0 (negative)
    [[nodiscard]] double lcLimit() const;     ///< LC-CUSUM h
};

struct LearningCurve {
    std::vector<double> cusum;    ///< S_n after each procedure
    std::vector<double> lcCusum;  ///< LC-CUSUM S_n after each procedure
    int competentAt = 0;          ///< 1-based procedure where LC-CUSUM first reached h; 0: not yet
    int unacceptableAt = 0;       ///< 1-based procedure where CUSUM first crossed h1; 0: never
};

/// `failures[n]` true when procedure n failed.
[[nodiscard]] LearningCurve learningCurve(const std::vector<bool>& failures,
                                          const CusumParameters& parameters);

}  // namespace colonosim::scoring
