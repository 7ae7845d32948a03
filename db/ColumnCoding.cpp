#include "db/ColumnCoding.h"

#include <bit>

namespace colonosim::db {

namespace {
std::uint64_t predict(const std::uint64_t* previous, size_t k)
{
    if (k >= 2) {
        return 2 * previous[k - 1] - previous[k - 2];
    }
    return k == 1 ? previous[0] : 0;
}
}  // namespace

void appendColumn(std::vector<char>& out, std::span<const double> values)
{
    const size_t n = values.size();
    std::vector<std::uint64_t> bits(n), residual(n);
    for (size_t k = 0; k < n; ++k) {
        bits[k] = std::bit_cast<std::uint64_t>(values[k]);
        const auto r = static_cast<std::int64_t>(bits[k] - predict(bits.data(), k));
        residual[k] = (static_cast<std::uint64_t>(r) << 1) ^ static_cast<std::uint64_t>(r >> 63);  // zigzag
    }
    const size_t at = out.size();
    out.resize(at + 8 * n);
    for (size_t plane = 0; plane < 8; ++plane) {
        char* p = out.data() + at + plane * n;
        for (size_t k = 0; k < n; ++k) {
            p[k] = static_cast<char>((residual[k] >> (8 * plane)) & 0xff);
        }
    }
}

std::vector<double> takeColumn(const std::vector<char>& in, size_t& at, size_t n)
{
    if (n > (in.size() - std::min(at, in.size())) / 8) {
        throw std::out_of_range("column of " + std::to_string(n) + " values runs past the end");
    }
    std::vector<std::uint64_t> residual(n, 0), bits(n);
    for (size_t plane = 0; plane < 8; ++plane) {
        const char* p = in.data() + at + plane * n;
        for (size_t k = 0; k < n; ++k) {
            residual[k] |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[k])) << (8 * plane);
        }
    }
    at += 8 * n;
    std::vector<double> values(n);
    for (size_t k = 0; k < n; ++k) {
        const std::uint64_t r = (residual[k] >> 1) ^ (~(residual[k] & 1) + 1);  // un-zigzag
        bits[k] = predict(bits.data(), k) + r;
        values[k] = std::bit_cast<double>(bits[k]);
    }
    return values;
}

}  // namespace colonosim::db
