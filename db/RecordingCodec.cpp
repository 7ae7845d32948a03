#include "db/RecordingCodec.h"

#include "db/ColumnCoding.h"

#include <zstd.h>

#include <bit>
#include <cstdint>
#include <cstring>

namespace colonosim::db {

namespace {
constexpr char kMagic[8] = {'C', 'S', 'R', 'E', 'C', '0', '0', '2'};
constexpr int kDoubleColumns = 10;
constexpr int kZstdLevel = 3;  // zstd's default: fast enough for the 1 s store target

double column(const procedure::RecordedSample& s, int c)
{
    switch (c) {
    case 0: return s.time;
    case 1: return s.insertion;
    case 2: return s.tip.x();
    case 3: return s.tip.y();
    case 4: return s.tip.z();
    case 5: return s.handleForce;
    case 6: return s.handleTorque;
    case 7: return s.maxWallForce;
    case 8: return s.mesenteryStrain;
    default: return s.discomfort;
    }
}

void setColumn(procedure::RecordedSample& s, int c, double v)
{
    switch (c) {
    case 0: s.time = v; break;
    case 1: s.insertion = v; break;
    case 2: s.tip.x() = v; break;
    case 3: s.tip.y() = v; break;
    case 4: s.tip.z() = v; break;
    case 5: s.handleForce = v; break;
    case 6: s.handleTorque = v; break;
    case 7: s.maxWallForce = v; break;
    case 8: s.mesenteryStrain = v; break;
    default: s.discomfort = v; break;
    }
}

template <class T>
void put(std::vector<char>& out, T value)
{
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <class T>
T take(const std::vector<char>& in, size_t& at, const char* what)
{
    if (at + sizeof(T) > in.size()) {
        throw RecordingCodecError(std::string("recording: truncated at ") + what + " (byte " +
                                  std::to_string(at) + " of " + std::to_string(in.size()) + ")");
    }
    T value;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}
}  // namespace

std::vector<char> encodeRecording(const procedure::Recording& recording)
{
    std::vector<char> raw;
    const size_t n = recording.samples.size();
    raw.reserve(n * (kDoubleColumns * 8 + 2) + recording.events.size() * 32);
    std::vector<double> values(n);
    for (int c = 0; c < kDoubleColumns; ++c) {
        for (size_t k = 0; k < n; ++k) {
            values[k] = column(recording.samples[k], c);
        }
        appendColumn(raw, values);
    }
    for (const auto& s : recording.samples) {
        put(raw, static_cast<std::uint8_t>(s.segment));
    }
    for (const auto& s : recording.samples) {
        put(raw, static_cast<std::uint8_t>(s.loop));
    }
    for (const auto& e : recording.events) {
        put(raw, std::bit_cast<std::uint64_t>(e.time));
        put(raw, static_cast<std::uint8_t>(e.kind));
        put(raw, static_cast<std::uint32_t>(e.detail.size()));
        raw.insert(raw.end(), e.detail.begin(), e.detail.end());
    }
    std::vector<char> compressed(ZSTD_compressBound(raw.size()));
    const size_t size =
        ZSTD_compress(compressed.data(), compressed.size(), raw.data(), raw.size(), kZstdLevel);
    if (ZSTD_isError(size)) {
        throw RecordingCodecError(std::string("recording: zstd: ") + ZSTD_getErrorName(size));
    }
    std::vector<char> out(kMagic, kMagic + 8);
    put(out, static_cast<std::uint64_t>(n));
    put(out, static_cast<std::uint64_t>(recording.events.size()));
    put(out, static_cast<std::uint64_t>(size));
    const size_t header = out.size();
    out.resize(header + size);
    std::memcpy(out.data() + header, compressed.data(), size);
    return out;
}

procedure::Recording decodeRecording(const std::vector<char>& bytes)
{
    if (bytes.size() < 32 || std::memcmp(bytes.data(), kMagic, 8) != 0) {
        throw RecordingCodecError("recording: not a stored recording (magic \"CSREC002\" expected)");
    }
    size_t at = 8;
    const auto n = take<std::uint64_t>(bytes, at, "sample count");
    const auto numEvents = take<std::uint64_t>(bytes, at, "event count");
    const auto size = take<std::uint64_t>(bytes, at, "compressed size");
    if (size != bytes.size() - at) {
        throw RecordingCodecError("recording: compressed size " + std::to_string(size) +
                                  " does not match the " + std::to_string(bytes.size() - at) +
                                  " bytes present");
    }
    const unsigned long long rawSize = ZSTD_getFrameContentSize(bytes.data() + at, size);
    if (rawSize == ZSTD_CONTENTSIZE_ERROR || rawSize == ZSTD_CONTENTSIZE_UNKNOWN ||
        rawSize < n * (kDoubleColumns * 8 + 2) + numEvents * 13) {
        throw RecordingCodecError("recording: corrupt zstd frame");
    }
    std::vector<char> raw(rawSize);
    const size_t got = ZSTD_decompress(raw.data(), raw.size(), bytes.data() + at, size);
    if (ZSTD_isError(got) || got != rawSize) {
        throw RecordingCodecError("recording: corrupt zstd frame");
    }
    procedure::Recording recording;
    recording.samples.resize(n);
    size_t r = 0;
    for (int c = 0; c < kDoubleColumns; ++c) {
        const std::vector<double> values = takeColumn(raw, r, n);
        for (size_t k = 0; k < n; ++k) {
            setColumn(recording.samples[k], c, values[k]);
        }
    }
    // Enumerations are checked before they are cast: a damaged blob is an error, never a bad value.
    for (auto& s : recording.samples) {
        const auto segment = take<std::uint8_t>(raw, r, "segments");
        if (segment >= geometry::kNumSegments) {
            throw RecordingCodecError("recording: segment " + std::to_string(segment) + " is outside [0, " +
                                      std::to_string(geometry::kNumSegments - 1) + "]");
        }
        s.segment = static_cast<geometry::Segment>(segment);
    }
    for (auto& s : recording.samples) {
        const auto loop = take<std::uint8_t>(raw, r, "loops");
        if (loop > static_cast<std::uint8_t>(procedure::LoopKind::ReverseSplenic)) {
            throw RecordingCodecError("recording: loop kind " + std::to_string(loop) + " is outside [0, " +
                                      std::to_string(static_cast<int>(procedure::LoopKind::ReverseSplenic)) +
                                      "]");
        }
        s.loop = static_cast<procedure::LoopKind>(loop);
    }
    recording.events.resize(numEvents);
    for (auto& e : recording.events) {
        e.time = std::bit_cast<double>(take<std::uint64_t>(raw, r, "events"));
        const auto kind = take<std::uint8_t>(raw, r, "events");
        if (kind > static_cast<std::uint8_t>(procedure::kLastEventKind)) {
            throw RecordingCodecError("recording: event kind " + std::to_string(kind) + " is outside [0, " +
                                      std::to_string(static_cast<int>(procedure::kLastEventKind)) + "]");
        }
        e.kind = static_cast<procedure::EventKind>(kind);
        const auto length = take<std::uint32_t>(raw, r, "events");
        if (r + length > raw.size()) {
            throw RecordingCodecError("recording: truncated event detail");
        }
        e.detail.assign(raw.data() + r, length);
        r += length;
    }
    return recording;
}

}  // namespace colonosim::db
