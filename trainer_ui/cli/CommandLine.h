#pragma once
/// \file
/// A small parser for `colonosim SUBCOMMAND [--flag] [--option VALUE] [ARG...]`.
/// Bad input raises UsageError, which main() turns into a message on stderr
/// and exit status 2.

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace colonosim::cli {

class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

class CommandLine {
public:
    /// `args` excludes the program and subcommand names. `flags` take no
    /// value; `options` take one. Unknown --names are refused.
    CommandLine(std::span<char* const> args, std::vector<std::string> flags,
                std::vector<std::string> options);

    [[nodiscard]] bool has(const std::string& flag) const;
    [[nodiscard]] std::optional<std::string> value(const std::string& option) const;
    /// A number option within [min, max]; the message names option, value and range.
    [[nodiscard]] double number(const std::string& option, double fallback, double min, double max,
                                const std::string& unit) const;
    [[nodiscard]] const std::vector<std::string>& positional() const { return m_positional; }

private:
    std::vector<std::string> m_flags;
    std::vector<std::pair<std::string, std::string>> m_values;
    std::vector<std::string> m_positional;
};

}  // namespace colonosim::cli
