#pragma once
/// \file
/// Comma-separated numeric arguments of the report commands
/// (contact_stability, construct_validity): each value is checked against
/// its range, and a bad one is refused naming the flag, the value and the range.

#include <cstdint>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace colonosim::bench {

/// The shortest text of `value` (as a stream writes it).
inline std::string shortest(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

/// The number `text` in [low, high]; throws std::invalid_argument naming
/// `flag`, the text and the range otherwise.
inline double parseNumber(const std::string& flag, const std::string& text, double low, double high)
{
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || !(value >= low && value <= high)) {
        throw std::invalid_argument(flag + ": value '" + text + "' is not a number in [" + shortest(low) +
                                    ", " + shortest(high) + "]");
    }
    return value;
}

/// Values of `text` ("1,2.5,3"), each in [low, high]; throws std::invalid_argument otherwise.
inline std::vector<double> parseList(const std::string& flag, const std::string& text, double low,
                                     double high)
{
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        values.push_back(parseNumber(flag, item, low, high));
    }
    if (values.empty()) {
        throw std::invalid_argument(flag + ": no values given");
    }
    return values;
}

/// Patient seeds: whole numbers in [0, 1e9]; throws std::invalid_argument otherwise.
inline std::vector<std::uint64_t> parseSeeds(const std::string& flag, const std::string& text)
{
    std::vector<std::uint64_t> seeds;
    for (const double seed : parseList(flag, text, 0.0, 1e9)) {
        if (seed != static_cast<double>(static_cast<std::uint64_t>(seed))) {
            throw std::invalid_argument(flag + ": value " + shortest(seed) +
                                        " is not a whole number in [0, 1e+09]");
        }
        seeds.push_back(static_cast<std::uint64_t>(seed));
    }
    return seeds;
}

/// Calls `option(flag, value)` for each "--flag value" pair of the command
/// line; throws std::invalid_argument for a flag without its value.
template <typename Option>
void forEachOption(int argc, char** argv, Option option)
{
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) {
            throw std::invalid_argument(flag + ": a value is needed");
        }
        option(flag, std::string(argv[++i]));
    }
}

}  // namespace colonosim::bench
