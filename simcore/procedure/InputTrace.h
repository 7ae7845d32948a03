#pragma once
/// \file
/// The input trace: every InputSample of a session at the loop rate,
/// recorded losslessly. With the case and the simulator version it fully
/// determines the session (ARCHITECTURE.md, determinism and replay).
///
/// File format (little-endian):
///   magic "CSTRACE1", uint32 format version (1), double loop step (s),
///   uint64 sample count, uint64 compressed size, then a zstd frame holding
///   five channels one after the other: the IEEE-754 bit patterns of
///   insertion, rotation, dialUpDown, dialLeftRight (uint64 each) XOR-ed with
///   the previous sample's (delta coding: a value that changes little or not
///   at all becomes mostly zero bytes), then the button bytes.
/// XOR of bit patterns is exactly invertible, so the round trip is bit-exact.

#include "simcore/procedure/DeviceInput.h"

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace colonosim::procedure {

class TraceError : public std::runtime_error {
public:
    explicit TraceError(const std::string& message) : std::runtime_error(message) {}
};

struct InputTrace {
    double loopStep = 1e-3;  ///< s
    std::vector<InputSample> samples;

    friend bool operator==(const InputTrace&, const InputTrace&) = default;
};

/// Serialises (delta coding + zstd).
[[nodiscard]] std::vector<char> encodeTrace(const InputTrace& trace);
/// Parses; throws TraceError naming what is wrong ("FILE: ..." when read from a file).
[[nodiscard]] InputTrace decodeTrace(const std::vector<char>& bytes, const std::string& label = "trace");

void writeTrace(const std::filesystem::path& path, const InputTrace& trace);
[[nodiscard]] InputTrace readTrace(const std::filesystem::path& path);

}  // namespace colonosim::procedure
