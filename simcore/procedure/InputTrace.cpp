#include "simcore/procedure/InputTrace.h"

#include <zstd.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace colonosim::procedure {

namespace {
constexpr std::array<char, 8> kMagic{'C', 'S', 'T', 'R', 'A', 'C', 'E', '1'};
constexpr std::uint32_t kVersion = 1;
constexpr int kChannels = 4;
constexpr size_t kHeaderSize = 8 + 4 + 8 + 8 + 8;
constexpr std::uint64_t kMaxSamples = 24ULL * 3600 * 10000;  // a day at 10 kHz

template <class T>
void put(std::vector<char>& out, T value)
{
    const size_t at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &value, sizeof(T));
}

template <class T>
T get(const std::vector<char>& in, size_t offset)
{
    T value;
    std::memcpy(&value, in.data() + offset, sizeof(T));
    return value;
}

double channel(const InputSample& s, int c)
{
    switch (c) {
    case 0: return s.insertion;
    case 1: return s.rotation;
    case 2: return s.dialUpDown;
    default: return s.dialLeftRight;
    }
}

void setChannel(InputSample& s, int c, double value)
{
    switch (c) {
    case 0: s.insertion = value; break;
    case 1: s.rotation = value; break;
    case 2: s.dialUpDown = value; break;
    default: s.dialLeftRight = value; break;
    }
}
}  // namespace

std::vector<char> encodeTrace(const InputTrace& trace)
{
    const size_t n = trace.samples.size();
    std::vector<char> raw;
    raw.reserve(n * (kChannels * 8 + 1));
    for (int c = 0; c < kChannels; ++c) {
        std::uint64_t previous = 0;
        for (const InputSample& s : trace.samples) {
            const auto bits = std::bit_cast<std::uint64_t>(channel(s, c));
            put(raw, bits ^ previous);
            previous = bits;
        }
    }
    for (const InputSample& s : trace.samples) {
        raw.push_back(static_cast<char>(s.buttons));
    }
    std::vector<char> compressed(ZSTD_compressBound(raw.size()));
    const size_t size = ZSTD_compress(compressed.data(), compressed.size(), raw.data(), raw.size(), 19);
    if (ZSTD_isError(size) != 0U) {
        throw TraceError(std::string("trace: compression failed: ") + ZSTD_getErrorName(size));
    }
    std::vector<char> out;
    out.reserve(kHeaderSize + size);
    out.resize(kMagic.size());
    std::memcpy(out.data(), kMagic.data(), kMagic.size());
    put(out, kVersion);
    put(out, trace.loopStep);
    put(out, static_cast<std::uint64_t>(n));
    put(out, static_cast<std::uint64_t>(size));
    out.insert(out.end(), compressed.begin(), compressed.begin() + static_cast<std::ptrdiff_t>(size));
    return out;
}

InputTrace decodeTrace(const std::vector<char>& bytes, const std::string& label)
{
    if (bytes.size() < kHeaderSize || !std::equal(kMagic.begin(), kMagic.end(), bytes.begin())) {
        throw TraceError(label + ": not a colonosim input trace (missing \"CSTRACE1\" header)");
    }
    const auto version = get<std::uint32_t>(bytes, 8);
    if (version != kVersion) {
        throw TraceError(label + ": trace format version " + std::to_string(version) +
                         " is not supported (1)");
    }
    InputTrace trace;
    trace.loopStep = get<double>(bytes, 12);
    const auto n = get<std::uint64_t>(bytes, 20);
    const auto size = get<std::uint64_t>(bytes, 28);
    if (!(trace.loopStep >= 1e-5 && trace.loopStep <= 1e-2)) {
        throw TraceError(label + ": loop step " + std::to_string(trace.loopStep) +
                         " s is outside [1e-05, 0.01] s");
    }
    if (n > kMaxSamples) {
        throw TraceError(label + ": sample count " + std::to_string(n) + " is outside [0, " +
                         std::to_string(kMaxSamples) + "]");
    }
    if (size != bytes.size() - kHeaderSize) {
        throw TraceError(label + ": compressed size " + std::to_string(size) + " does not match the " +
                         std::to_string(bytes.size() - kHeaderSize) + " bytes present (truncated file?)");
    }
    const size_t rawSize = static_cast<size_t>(n) * (kChannels * 8 + 1);
    std::vector<char> raw(rawSize);
    const size_t got = ZSTD_decompress(raw.data(), raw.size(), bytes.data() + kHeaderSize, size);
    if (ZSTD_isError(got) != 0U || got != rawSize) {
        throw TraceError(label + ": corrupt trace data (" +
                         (ZSTD_isError(got) != 0U
                              ? std::string(ZSTD_getErrorName(got))
                              : std::to_string(got) + " of " + std::to_string(rawSize) + " bytes") +
                         ")");
    }
    trace.samples.resize(static_cast<size_t>(n));
    for (int c = 0; c < kChannels; ++c) {
        std::uint64_t previous = 0;
        for (size_t i = 0; i < n; ++i) {
            previous ^= get<std::uint64_t>(raw, (static_cast<size_t>(c) * n + i) * 8);
            setChannel(trace.samples[i], c, std::bit_cast<double>(previous));
        }
    }
    for (size_t i = 0; i < n; ++i) {
        trace.samples[i].buttons = static_cast<std::uint8_t>(raw[kChannels * 8 * n + i]);
    }
    return trace;
}

void writeTrace(const std::filesystem::path& path, const InputTrace& trace)
{
    const std::vector<char> bytes = encodeTrace(trace);
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
        throw TraceError(path.string() + ": cannot write the trace");
    }
}

InputTrace readTrace(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw TraceError(path.string() + ": cannot open the trace");
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decodeTrace(bytes, path.string());
}

}  // namespace colonosim::procedure
