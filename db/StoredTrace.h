#pragma once
/// \file
/// The stored form of a session's input trace (the `trace` BLOB), lossless:
/// decoding gives back the InputTrace bit for bit, so the session replays
/// exactly (ReplayOperator). It differs from the trace file of
/// `colonosim run` (simcore's InputTrace format: XOR delta, zstd level 19) to
/// meet the store-time and size targets: linear prediction of the bit
/// patterns (ColumnCoding.h) and zstd level 3.
///
/// Layout (little-endian): magic "CSTRDB01", double loop step (s), uint64
/// sample count, uint64 compressed size, then one zstd frame holding the
/// insertion, rotation, dialUpDown and dialLeftRight columns and the button bytes.

#include "simcore/procedure/InputTrace.h"

#include <vector>

namespace colonosim::db {

[[nodiscard]] std::vector<char> encodeStoredTrace(const procedure::InputTrace& trace);
/// Throws procedure::TraceError naming what is wrong.
[[nodiscard]] procedure::InputTrace decodeStoredTrace(const std::vector<char>& bytes);

}  // namespace colonosim::db
