#pragma once
/// \file
/// Lossless coding of sampled double columns for storage: each value's
/// IEEE-754 bit pattern is predicted from the two before it by linear
/// extrapolation in the integer domain (2 b[k-1] - b[k-2], wrapping uint64
/// arithmetic), the residual is zigzag-coded and the residuals are written
/// byte plane by byte plane. For a smoothly varying signal with a steady
/// exponent, the bit pattern is nearly linear in the value, so residuals are
/// small and the high byte planes are all zeros, which zstd then removes.
/// Integer arithmetic makes the round trip exact on every platform.

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace colonosim::db {

/// Appends the coded column (values.size() * 8 bytes) to `out`.
void appendColumn(std::vector<char>& out, std::span<const double> values);
/// Reads `n` values coded by appendColumn from `in` at `at`, advancing it.
/// Throws std::out_of_range when `in` is too short.
[[nodiscard]] std::vector<double> takeColumn(const std::vector<char>& in, size_t& at, size_t n);

}  // namespace colonosim::db
