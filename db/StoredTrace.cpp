#include "db/StoredTrace.h"

#include "db/ColumnCoding.h"

#include <zstd.h>

#include <bit>
#include <cstring>

namespace colonosim::db {

namespace {
constexpr char kMagic[8] = {'C', 'S', 'T', 'R', 'D', 'B', '0', '1'};
constexpr int kZstdLevel = 3;

template <class T>
void put(std::vector<char>& out, T value)
{
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <class T>
T take(const std::vector<char>& in, size_t& at)
{
    if (at + sizeof(T) > in.size()) {
        throw procedure::TraceError("stored trace: truncated header");
    }
    T value;
    std::memcpy(&value, in.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

double channel(const procedure::InputSample& s, int c)
{
    switch (c) {
    case 0: return s.insertion;
    case 1: return s.rotation;
    case 2: return s.dialUpDown;
    default: return s.dialLeftRight;
    }
}
}  // namespace

std::vector<char> encodeStoredTrace(const procedure::InputTrace& trace)
{
    const size_t n = trace.samples.size();
    std::vector<char> raw;
    raw.reserve(n * 33);
    std::vector<double> values(n);
    for (int c = 0; c < 4; ++c) {
        for (size_t k = 0; k < n; ++k) {
            values[k] = channel(trace.samples[k], c);
        }
        appendColumn(raw, values);
    }
    for (const auto& s : trace.samples) {
        raw.push_back(static_cast<char>(s.buttons));
    }
    std::vector<char> compressed(ZSTD_compressBound(raw.size()));
    const size_t size =
        ZSTD_compress(compressed.data(), compressed.size(), raw.data(), raw.size(), kZstdLevel);
    if (ZSTD_isError(size)) {
        throw procedure::TraceError(std::string("stored trace: zstd: ") + ZSTD_getErrorName(size));
    }
    std::vector<char> out(kMagic, kMagic + 8);
    put(out, trace.loopStep);
    put(out, static_cast<std::uint64_t>(n));
    put(out, static_cast<std::uint64_t>(size));
    const size_t header = out.size();
    out.resize(header + size);
    std::memcpy(out.data() + header, compressed.data(), size);
    return out;
}

procedure::InputTrace decodeStoredTrace(const std::vector<char>& bytes)
{
    if (bytes.size() < 32 || std::memcmp(bytes.data(), kMagic, 8) != 0) {
        throw procedure::TraceError("stored trace: not a stored trace (magic \"CSTRDB01\" expected)");
    }
    size_t at = 8;
    procedure::InputTrace trace;
    trace.loopStep = take<double>(bytes, at);
    const auto n = take<std::uint64_t>(bytes, at);
    const auto size = take<std::uint64_t>(bytes, at);
    if (size != bytes.size() - at) {
        throw procedure::TraceError("stored trace: compressed size " + std::to_string(size) +
                                    " does not match the " + std::to_string(bytes.size() - at) +
                                    " bytes present");
    }
    const unsigned long long rawSize = ZSTD_getFrameContentSize(bytes.data() + at, size);
    if (rawSize != n * 33) {
        throw procedure::TraceError("stored trace: corrupt zstd frame");
    }
    std::vector<char> raw(rawSize);
    if (ZSTD_decompress(raw.data(), raw.size(), bytes.data() + at, size) != rawSize) {
        throw procedure::TraceError("stored trace: corrupt zstd frame");
    }
    trace.samples.resize(n);
    size_t r = 0;
    for (int c = 0; c < 4; ++c) {
        const std::vector<double> values = takeColumn(raw, r, n);
        for (size_t k = 0; k < n; ++k) {
            auto& s = trace.samples[k];
            (c == 0   ? s.insertion
             : c == 1 ? s.rotation
             : c == 2 ? s.dialUpDown
                      : s.dialLeftRight) = values[k];
        }
    }
    for (auto& s : trace.samples) {
        s.buttons = static_cast<std::uint8_t>(raw[r++]);
    }
    return trace;
}

}  // namespace colonosim::db
