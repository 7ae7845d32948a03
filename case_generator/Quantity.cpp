#include "case_generator/Quantity.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace colonosim::cases {

std::string formatFixed(double value, int decimals)
{
    std::array<char, 64> buffer{};
    if (value == 0.0) {
        value = 0.0;  // never "-0.0"
    }
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                      std::chars_format::fixed, decimals);
    std::string text(buffer.data(), result.ptr);
    if (text.starts_with('-') && text.find_first_not_of("-0.") == std::string::npos) {
        text.erase(0, 1);
    }
    return text;
}

std::optional<double> parseNumber(std::string_view text)
{
    if (text.empty() || text.front() == '+') {
        return std::nullopt;
    }
    double value = 0.0;
    const auto result =
        std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

double Quantity::quantise(double si) const
{
    const std::optional<double> parsed = parseNumber(formatFixed(si / siPerUnit, decimals));
    return parsed ? *parsed * siPerUnit : si;
}

double Quantity::quantiseWithin(double si, const params::ParameterSpec& spec) const
{
    double step = siPerUnit;
    for (int i = 0; i < decimals; ++i) {
        step /= 10.0;
    }
    // A bound itself may come back an ulp outside (0.7 m as 70.0 * 0.01);
    // that is the bound, not a step beyond it.
    const double slack = 1e-12 * std::max(std::abs(spec.minValue), std::abs(spec.maxValue));
    double v = quantise(std::clamp(si, spec.minValue, spec.maxValue));
    if (v > spec.maxValue + slack) {
        v = quantise(v - step);
    } else if (v < spec.minValue - slack) {
        v = quantise(v + step);
    }
    return v;
}

std::string Quantity::format(double si) const
{
    return formatFixed(si / siPerUnit, decimals);
}

bool Quantity::accepts(double fileValue) const
{
    const double slack = 1e-9 * std::max(1.0, std::abs(max));
    return fileValue >= min - slack && fileValue <= max + slack;
}

Quantity Quantity::withRangeOf(const params::ParameterSpec& spec) const
{
    Quantity q = *this;
    q.min = spec.minValue / siPerUnit;
    q.max = spec.maxValue / siPerUnit;
    return q;
}

}  // namespace colonosim::cases
