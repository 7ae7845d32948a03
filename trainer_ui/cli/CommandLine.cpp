#include "trainer_ui/cli/CommandLine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace colonosim::cli {

CommandLine::CommandLine(std::span<char* const> args, std::vector<std::string> flags,
                         std::vector<std::string> options)
{
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string arg = args[i];
        if (arg.rfind("--", 0) != 0) {
            m_positional.push_back(arg);
            continue;
        }
        if (std::find(flags.begin(), flags.end(), arg) != flags.end()) {
            m_flags.push_back(arg);
        } else if (std::find(options.begin(), options.end(), arg) != options.end()) {
            if (i + 1 >= args.size()) {
                throw UsageError(arg + " needs a value");
            }
            m_values.emplace_back(arg, args[++i]);
        } else {
            throw UsageError("unknown option " + arg + " (see --help)");
        }
    }
}

bool CommandLine::has(const std::string& flag) const
{
    return std::find(m_flags.begin(), m_flags.end(), flag) != m_flags.end();
}

std::optional<std::string> CommandLine::value(const std::string& option) const
{
    for (const auto& [name, text] : m_values) {
        if (name == option) {
            return text;
        }
    }
    return std::nullopt;
}

double CommandLine::number(const std::string& option, double fallback, double min, double max,
                           const std::string& unit) const
{
    const std::optional<std::string> text = value(option);
    if (!text) {
        return fallback;
    }
    size_t used = 0;
    double parsed = NAN;
    try {
        parsed = std::stod(*text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text->size() || !(parsed >= min && parsed <= max)) {
        std::ostringstream out;
        out << option << " = " << *text << " is not a number in the allowed range [" << min << ", " << max
            << "] " << unit;
        throw UsageError(out.str());
    }
    return parsed;
}

}  // namespace colonosim::cli
