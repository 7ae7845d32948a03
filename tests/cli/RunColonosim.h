#pragma once
// Runs the `colonosim` executable (COLONOSIM_EXECUTABLE, set by CMake) as a
// person or a script would, capturing its exit status and output.

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace colonosim::testing {

struct Result {
    int status = -1;
    std::string output;  ///< stdout, and stderr unless stdoutOnly
};

/// Runs `executable` with `arguments` through the shell.
inline Result runCommand(const std::string& executable, const std::string& arguments, bool stdoutOnly = false)
{
    const std::string command = executable + " " + arguments + (stdoutOnly ? " 2>/dev/null" : " 2>&1");
    Result result;
    FILE* pipe = popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (pipe != nullptr && fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
        result.output += buffer.data();
    }
    const int raw = pipe != nullptr ? pclose(pipe) : -1;
    result.status = raw >= 0 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return result;
}

inline Result runColonosim(const std::string& arguments, bool stdoutOnly = false)
{
    return runCommand(COLONOSIM_EXECUTABLE, arguments, stdoutOnly);
}

}  // namespace colonosim::testing
