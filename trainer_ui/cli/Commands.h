#pragma once
/// \file
/// The headless subcommands of `colonosim`. Each returns the exit status:
/// 0 on success, 2 on bad input (after printing a message to stderr).

#include <span>

namespace colonosim::cli {

int runDemo(std::span<char* const> args);
int runParams(std::span<char* const> args);
int runMesh(std::span<char* const> args);
int runBench(std::span<char* const> args);
int runProcedure(std::span<char* const> args);
int runRod(std::span<char* const> args);
int runCase(std::span<char* const> args);
int runUser(std::span<char* const> args);
int runRules(std::span<char* const> args);
int runProgress(std::span<char* const> args);
int runReport(std::span<char* const> args);
int runBackup(std::span<char* const> args);
int runBenchmarks(std::span<char* const> args);
int runRender(std::span<char* const> args);

}  // namespace colonosim::cli
