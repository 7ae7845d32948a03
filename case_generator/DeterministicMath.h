#pragma once
/// \file
/// Elementary functions built from IEEE-754 basic operations only (+, -, *, /,
/// sqrt, ldexp, frexp), so that the case generator gives bit-identical results
/// on every conforming machine. libm's exp and log are not correctly rounded
/// and differ between implementations in the last bit; these do not depend
/// on libm. The library is compiled with -ffp-contract=off so that no fused
/// multiply-add changes a rounding.
///
/// - exp(x) = 2^k exp(r), k = round(x / ln 2), |r| <= ln 2 / 2, exp(r) by its
///   Taylor series to 20 terms (relative error < 1e-15).
/// - log(x) = e ln 2 + 2 atanh((m - 1) / (m + 1)), x = m 2^e, m in [sqrt(1/2), sqrt 2).
/// - normalQuantile(p): Acklam's rational approximation (relative error
///   1.15e-9), with one Newton-free tail formula using log and sqrt.

namespace colonosim::cases::detmath {

[[nodiscard]] double exp(double x);
[[nodiscard]] double log(double x);
/// The standard normal quantile, p in (0, 1).
[[nodiscard]] double normalQuantile(double p);

}  // namespace colonosim::cases::detmath
