// The stored input trace round-trips bit for bit, including values whose bit
// patterns jump (sign changes, zeros, infinities, NaN payloads, denormals);
// a smooth trace compresses well; corrupt bytes are refused.
#include "db/StoredTrace.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace {

using namespace colonosim;

bool bitEqual(const procedure::InputTrace& a, const procedure::InputTrace& b)
{
    if (a.samples.size() != b.samples.size() ||
        std::bit_cast<std::uint64_t>(a.loopStep) != std::bit_cast<std::uint64_t>(b.loopStep)) {
        return false;
    }
    for (size_t k = 0; k < a.samples.size(); ++k) {
        const auto& x = a.samples[k];
        const auto& y = b.samples[k];
        for (auto [p, q] :
             {std::pair{x.insertion, y.insertion}, std::pair{x.rotation, y.rotation},
              std::pair{x.dialUpDown, y.dialUpDown}, std::pair{x.dialLeftRight, y.dialLeftRight}}) {
            if (std::bit_cast<std::uint64_t>(p) != std::bit_cast<std::uint64_t>(q)) {
                return false;
            }
        }
        if (x.buttons != y.buttons) {
            return false;
        }
    }
    return true;
}

TEST(StoredTrace, RoundTripIsBitExactForAwkwardValues)
{
    procedure::InputTrace trace;
    trace.loopStep = 1e-3;
    const double awkward[] = {0.0,
                              -0.0,
                              1.0,
                              -1.0,
                              std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN(),
                              std::numeric_limits<double>::denorm_min(),
                              1e308,
                              -1e-308,
                              0.1,
                              3.0};
    for (size_t k = 0; k < 500; ++k) {
        procedure::InputSample s;
        s.insertion = 1e-4 * static_cast<double>(k);
        s.rotation = awkward[k % std::size(awkward)];
        s.dialUpDown = std::sin(0.01 * static_cast<double>(k));
        s.dialLeftRight = awkward[(k * 7) % std::size(awkward)];
        s.buttons = static_cast<std::uint8_t>(k % 5);
        trace.samples.push_back(s);
    }
    EXPECT_TRUE(bitEqual(db::decodeStoredTrace(db::encodeStoredTrace(trace)), trace));
    EXPECT_TRUE(bitEqual(db::decodeStoredTrace(db::encodeStoredTrace(procedure::InputTrace{})),
                         procedure::InputTrace{}));
}

TEST(StoredTrace, ASmoothTraceCompressesFarBelowItsRawSize)
{
    procedure::InputTrace trace;
    double insertion = 0.0;
    for (size_t k = 0; k < 100000; ++k) {
        procedure::InputSample s;
        insertion += 0.03 * trace.loopStep;  // 3 cm/s, accumulated as an operator does
        s.insertion = insertion;
        s.rotation = 0.5;
        trace.samples.push_back(s);
    }
    const auto bytes = db::encodeStoredTrace(trace);
    EXPECT_TRUE(bitEqual(db::decodeStoredTrace(bytes), trace));
    // Raw: 33 bytes per sample. A constant-speed ramp predicts almost exactly.
    EXPECT_LT(bytes.size(), trace.samples.size() * 2);
}

TEST(StoredTrace, CorruptBytesAreRefused)
{
    procedure::InputTrace trace;
    trace.samples.resize(10);
    auto bytes = db::encodeStoredTrace(trace);
    bytes.pop_back();
    EXPECT_THROW((void)db::decodeStoredTrace(bytes), procedure::TraceError);
    EXPECT_THROW((void)db::decodeStoredTrace(std::vector<char>(64, 'x')), procedure::TraceError);
}

}  // namespace
