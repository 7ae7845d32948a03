#pragma once
/// \file
/// The stored form of a procedure Recording (the `recording` BLOB of a
/// session), lossless so that metrics can be recomputed bit for bit.
///
/// Layout (little-endian): magic "CSREC002", uint64 sample count, uint64
/// event count, uint64 compressed size, then one zstd frame (level 3) holding
/// the sample columns one after the other (time, insertion, tip x/y/z, handle
/// force, handle torque, max wall force, mesentery strain, discomfort, each
/// coded by ColumnCoding.h; then segment and loop bytes), then the events
/// (time bits, kind byte, detail length uint32 and bytes).

#include "simcore/procedure/Recorder.h"

#include <stdexcept>
#include <vector>

namespace colonosim::db {

class RecordingCodecError : public std::runtime_error {
public:
    explicit RecordingCodecError(const std::string& message) : std::runtime_error(message) {}
};

[[nodiscard]] std::vector<char> encodeRecording(const procedure::Recording& recording);
/// Throws RecordingCodecError naming what is wrong.
[[nodiscard]] procedure::Recording decodeRecording(const std::vector<char>& bytes);

}  // namespace colonosim::db
