// The input trace: lossless, compact, and refusing bad files with a message.

#include "simcore/procedure/InputTrace.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

namespace colonosim::procedure {
namespace {

/// Ten minutes of plausible hands at 1 kHz: a slow insertion with jitter at
/// the encoder resolution (0.2 mm, 0.18 deg; seed 001), dials that move now
/// and then, a button pressed for a while.
InputTrace tenMinutes()
{
    InputTrace trace;
    std::mt19937 random(5);
    std::uniform_int_distribution<int> jitter(-1, 1);
    constexpr double mm = 2e-4;
    constexpr double deg = 0.18 * M_PI / 180.0;
    InputSample s;
    for (int i = 0; i < 600000; ++i) {
        if (i % 40 == 0) {
            s.insertion = std::clamp(s.insertion + mm * (1 + jitter(random)), 0.0, 1.6);
            s.rotation += deg * jitter(random);
        }
        if (i % 500 == 0) {
            s.dialUpDown = deg * std::round(30.0 * std::sin(i * 1e-4));
            s.dialLeftRight = deg * std::round(10.0 * std::cos(i * 7e-5));
        }
        s.buttons = (i / 20000) % 7 == 3 ? kWater : 0;
        trace.samples.push_back(s);
    }
    return trace;
}

TEST(InputTrace, RoundTripIsBitExact)
{
    InputTrace trace = tenMinutes();
    // Values whose bit patterns a lossy coder would lose.
    trace.samples[7].rotation = -0.0;
    trace.samples[8].dialUpDown = std::numeric_limits<double>::denorm_min();
    trace.samples[9].insertion = std::nextafter(1.0, 2.0);
    const InputTrace back = decodeTrace(encodeTrace(trace));
    ASSERT_EQ(back.samples.size(), trace.samples.size());
    EXPECT_EQ(back.loopStep, trace.loopStep);
    for (size_t i = 0; i < trace.samples.size(); ++i) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(back.samples[i].rotation),
                  std::bit_cast<std::uint64_t>(trace.samples[i].rotation))
            << i;
        ASSERT_EQ(back.samples[i], trace.samples[i]) << i;
    }
}

TEST(InputTrace, IsCompact)
{
    // Raw, the samples take 33 bytes each (19.8 MB for ten minutes).
    const InputTrace trace = tenMinutes();
    const std::vector<char> bytes = encodeTrace(trace);
    const double perSample = static_cast<double>(bytes.size()) / static_cast<double>(trace.samples.size());
    std::cout << "ten minutes at 1 kHz: " << bytes.size() << " bytes, " << perSample << " bytes per sample\n";
    EXPECT_LT(perSample, 2.0);
}

TEST(InputTrace, BadFilesAreRefusedWithAReason)
{
    const std::vector<char> good = encodeTrace(tenMinutes());
    struct Case {
        const char* label;
        std::vector<char> bytes;
        const char* expected;
    };
    std::vector<char> truncated(good.begin(), good.end() - 100);
    std::vector<char> corrupt = good;
    for (size_t i = 60; i < 80; ++i) {
        corrupt[i] = static_cast<char>(corrupt[i] ^ 0x5a);
    }
    std::vector<char> version = good;
    version[8] = 9;
    for (const Case& c :
         {Case{"empty", {}, "not a colonosim input trace"},
          Case{"text", std::vector<char>{'h', 'e', 'l', 'l', 'o'}, "not a colonosim input trace"},
          Case{"truncated", truncated, "truncated"}, Case{"corrupt", corrupt, "corrupt trace data"},
          Case{"version", version, "version 9"}}) {
        try {
            (void)decodeTrace(c.bytes, "session.trace");
            ADD_FAILURE() << c.label << " accepted";
        } catch (const TraceError& error) {
            EXPECT_NE(std::string(error.what()).find("session.trace: "), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find(c.expected), std::string::npos)
                << c.label << ": " << error.what();
        }
    }
    EXPECT_THROW((void)readTrace("/nonexistent/dir/x.trace"), TraceError);
}

TEST(InputTrace, FileRoundTrip)
{
    const auto path =
        std::filesystem::temp_directory_path() / ("colonosim_trace_" + std::to_string(::getpid()));
    InputTrace trace;
    trace.samples.resize(3);
    trace.samples[1].insertion = 0.25;
    trace.samples[2].buttons = kMarkLesion;
    writeTrace(path, trace);
    EXPECT_EQ(readTrace(path), trace);
    std::filesystem::remove(path);
}

struct BadInput {
    const char* label;
    InputSample sample;
    const char* field;
};

void PrintTo(const BadInput& b, std::ostream* out)
{
    *out << b.label;
}

class DeviceBoundary : public ::testing::TestWithParam<BadInput> {};

TEST_P(DeviceBoundary, RefusesWithFieldValueAndRange)
{
    const std::string reason = validateInput(GetParam().sample);
    ASSERT_FALSE(reason.empty()) << GetParam().label;
    EXPECT_NE(reason.find(GetParam().field), std::string::npos) << reason;
    EXPECT_NE(reason.find('['), std::string::npos) << "names the range: " << reason;
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, DeviceBoundary,
    ::testing::Values(
        BadInput{"nan_insertion", {std::nan(""), 0, 0, 0, 0}, "input.insertion"},
        BadInput{"negative_insertion", {-0.01, 0, 0, 0, 0}, "input.insertion"},
        BadInput{"huge_rotation", {0.1, 1e30, 0, 0, 0}, "input.rotation"},
        BadInput{"inf_dial", {0.1, 0, std::numeric_limits<double>::infinity(), 0, 0}, "input.dialUpDown"},
        BadInput{"nan_dial", {0.1, 0, 0, std::nan(""), 0}, "input.dialLeftRight"},
        BadInput{"unknown_button", {0.1, 0, 0, 0, 0x80}, "input.buttons"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(DeviceBoundary, AcceptsPlausibleInput)
{
    EXPECT_EQ(validateInput(InputSample{0.8, -3.0, 1.2, -0.5, kAir | kMarkLesion}), "");
}

}  // namespace
}  // namespace colonosim::procedure
