// The HDC link over loopback: the OpenIGTLink mapping round trip, one HDC at
// a time, garbage, oversized and corrupted messages, and a lost connection.
#include "simcore/devices/HdcController.h"
#include "simcore/devices/HdcServer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <thread>

namespace {

using namespace colonosim::devices;
using colonosim::procedure::InputSample;

/// Waits (real time) until `done` or 2 s.
template <class F>
bool waitFor(F done)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < end) {
        if (done()) {
            return true;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return false;
}

InputSample sample()
{
    InputSample s;
    s.insertion = 0.4321;
    s.rotation = 7.5;  // more than a turn: the SENSOR carries it, the matrix cannot
    s.dialUpDown = -1.25;
    s.dialLeftRight = 0.5;
    s.buttons = 5;
    return s;
}

TEST(HapticLink, InputAndLoadRoundTripOverLoopback)
{
    HdcServer server(0, HapticParameters{});
    TcpLink client = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    ASSERT_TRUE(client.send(encodeInput(sample(), 12.5)));
    std::optional<StampedInput> got;
    ASSERT_TRUE(waitFor([&] { return (got = server.latestInput()).has_value(); }));
    EXPECT_NEAR(got->input.insertion, 0.4321, 1e-6);  // float mm in the TRANSFORM
    EXPECT_DOUBLE_EQ(got->input.rotation, 7.5);
    EXPECT_DOUBLE_EQ(got->input.dialUpDown, -1.25);
    EXPECT_DOUBLE_EQ(got->input.dialLeftRight, 0.5);
    EXPECT_EQ(got->input.buttons, 5);
    EXPECT_NEAR(got->time, 12.5, 1e-6);
    EXPECT_TRUE(server.connected());

    server.publishLoad(HandleCommand{3.25, -0.125}, got->time);
    MessageReader reader(4096);
    Bytes bytes;
    std::optional<Message> load;
    ASSERT_TRUE(waitFor([&] {
        client.receive(bytes, 0.001);
        reader.feed(bytes.data(), bytes.size());
        bytes.clear();
        std::string error;
        load = reader.next(error);
        return load.has_value();
    }));
    EXPECT_EQ(load->kind, Message::Kind::HandleLoad);
    EXPECT_DOUBLE_EQ(load->values[0], 3.25);
    EXPECT_DOUBLE_EQ(load->values[1], -0.125);
    EXPECT_NEAR(load->time, 12.5, 1e-6);
}

/// CPU time of the calling thread, s.
double threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

TEST(HapticLink, TheLoopWaitsForAFrameOnItsCoreAndStepsOnTheFrameWhenItComes)
{
    HdcServer server(0, HapticParameters{});
    TcpLink client = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    ASSERT_TRUE(waitFor([&] { return server.connected(); }));
    // No frame: the wait ends at its timeout with nothing, having polled
    // (the thread's CPU time runs with the wait) rather than slept.
    const auto start = std::chrono::steady_clock::now();
    const double cpuBefore = threadCpuSeconds();
    EXPECT_FALSE(server.waitForInput(0.005).has_value());
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = threadCpuSeconds() - cpuBefore;
    EXPECT_GE(waited, 0.005);
    EXPECT_GT(cpu, 0.05 * waited) << "a sleeping wait uses almost no CPU: " << cpu << " s of " << waited
                                  << " s";
    // A frame sent during the wait ends it with that frame.
    std::jthread sender([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        client.send(encodeInput(sample(), 3.0));
    });
    const std::optional<StampedInput> got = server.waitForInput(1.0);
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->time, 3.0, 1e-6);
    EXPECT_FALSE(server.latestInput().has_value()) << "taken: nothing fresh until the next frame";
}

TEST(HapticLink, ASecondHdcIsRefusedWithAReason)
{
    HdcServer server(0, HapticParameters{});
    TcpLink first = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    ASSERT_TRUE(waitFor([&] { return server.connected(); }));
    TcpLink second = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    MessageReader reader(4096);
    Bytes bytes;
    std::optional<Message> status;
    ASSERT_TRUE(waitFor([&] {
        second.receive(bytes, 0.001);
        reader.feed(bytes.data(), bytes.size());
        bytes.clear();
        std::string error;
        status = reader.next(error);
        return status.has_value();
    }));
    EXPECT_EQ(status->kind, Message::Kind::Status);
    EXPECT_EQ(status->statusCode, kStatusBusy);
    EXPECT_NE(status->statusText.find("busy"), std::string::npos);
    EXPECT_EQ(server.refusedConnections(), 1);
    // The first HDC still drives.
    ASSERT_TRUE(first.send(encodeInput(sample(), 1.0)));
    EXPECT_TRUE(waitFor([&] { return server.latestInput().has_value(); }));
}

TEST(HapticLink, GarbageClosesTheLinkAndTheServerStaysUsable)
{
    HdcServer server(0, HapticParameters{});
    {
        TcpLink garbage = TcpLink::connect("127.0.0.1", server.port(), 1.0);
        const std::string http = "GET / HTTP/1.1\r\nHost: colonosim\r\n\r\n" + std::string(64, 'x');
        ASSERT_TRUE(garbage.send(Bytes(http.begin(), http.end())));
        ASSERT_TRUE(waitFor([&] { return server.refusedMessages() >= 1 && !server.connected(); }));
        EXPECT_FALSE(server.latestInput().has_value());
    }
    TcpLink good = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    ASSERT_TRUE(good.send(encodeInput(sample(), 2.0)));
    EXPECT_TRUE(waitFor([&] { return server.latestInput().has_value(); }));
}

TEST(HapticLink, AnOversizedMessageIsRefusedBeforeItsBodyIsRead)
{
    HapticParameters p;
    MessageReader reader(static_cast<std::size_t>(p.maxMessageBytes));
    Bytes frame = encodeInput(sample(), 1.0);
    // Body size: bytes 42..49 of the header (big-endian uint64): announce 10 MB.
    const std::uint64_t huge = 10'000'000;
    for (int i = 0; i < 8; ++i) {
        frame[static_cast<size_t>(42 + i)] = static_cast<std::uint8_t>(huge >> (8 * (7 - i)));
    }
    reader.feed(frame.data(), 58);
    std::string error;
    EXPECT_FALSE(reader.next(error).has_value());
    EXPECT_TRUE(reader.fatal());
    EXPECT_NE(error.find("bodySize = 10000000"), std::string::npos) << error;
}

TEST(HapticLink, ACorruptedBodyFailsItsCrcAndTheStreamStaysInStep)
{
    MessageReader reader(4096);
    Bytes a = encodeInput(sample(), 1.0);
    a[70] ^= 0x5a;  // inside the TRANSFORM's body
    const Bytes b = encodeInput(sample(), 2.0);
    a.insert(a.end(), b.begin(), b.end());
    reader.feed(a.data(), a.size());
    std::string error;
    int pose = 0, refused = 0, other = 0;
    for (;;) {
        const std::optional<Message> m = reader.next(error);
        if (m) {
            (m->kind == Message::Kind::Pose ? pose : other) += 1;
        } else if (!error.empty()) {
            ++refused;
            EXPECT_NE(error.find("CRC"), std::string::npos) << error;
        } else {
            break;
        }
    }
    EXPECT_EQ(refused, 1);
    EXPECT_EQ(pose, 1);   // the second frame's
    EXPECT_EQ(other, 4);  // both frames' angles and buttons
    EXPECT_FALSE(reader.fatal());
}

TEST(HapticLink, ANanLoadIsRefusedOnArrivalAndNeverApplied)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Bytes bytes = encodeHandleLoad(HandleCommand{nan, 0.0}, 1.0);
    MessageReader reader(4096);
    reader.feed(bytes.data(), bytes.size());
    std::string error;
    EXPECT_FALSE(reader.next(error).has_value());
    EXPECT_NE(error.find("not finite"), std::string::npos) << error;
}

TEST(HapticLink, OutOfRangeInputIsRefusedNamingTheField)
{
    InputSample s = sample();
    s.dialUpDown = 9.0;
    const Bytes bytes = encodeInput(s, 1.0);
    MessageReader reader(4096);
    reader.feed(bytes.data(), bytes.size());
    std::string error;
    std::string refusal;
    for (int i = 0; i < 3; ++i) {
        if (!reader.next(error) && !error.empty()) {
            refusal = error;
        }
    }
    EXPECT_NE(refusal.find("dialUpDown = 9"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("[-3.5, 3.5]"), std::string::npos) << refusal;
}

/// A hand that holds still at 10 cm.
InputSample still(double)
{
    return InputSample{0.1, 0.0, 0.0, 0.0, 0};
}

TEST(HapticLink, ALostConnectionBringsTheForceToZeroWithinFiveMilliseconds)
{
    SimulatedDevice device(still);
    HapticParameters parameters;
    auto server = std::make_unique<HdcServer>(0, parameters);
    HdcController hdc(device, parameters, "127.0.0.1", server->port());
    double now = 0.0;
    // Real time between ticks so the loopback carries the messages.
    auto tickOnce = [&] {
        now += parameters.servoPeriod;
        hdc.tick(now);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (auto in = server->latestInput()) {
            server->publishLoad(HandleCommand{20.0, 0.0}, in->time);
        }
    };
    for (int i = 0; i < 200 && hdc.servo().output().force < 20.0; ++i) {
        tickOnce();
    }
    ASSERT_DOUBLE_EQ(hdc.servo().output().force, 20.0);
    server.reset();  // the simulator goes away: its socket closes
    // The HDC sees the close on a tick; from that tick the force is zero within 5 ms.
    double seen = -1.0;
    for (int i = 0; i < 500 && seen < 0.0; ++i) {
        now += parameters.servoPeriod;
        hdc.tick(now);
        if (!hdc.connected()) {
            seen = now;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ASSERT_GE(seen, 0.0) << "the close was never seen";
    double zeroAt = seen;
    while (hdc.servo().output().force != 0.0) {
        now += parameters.servoPeriod;
        hdc.tick(now);
        zeroAt = now;
        ASSERT_LT(zeroAt - seen, 0.02);
    }
    EXPECT_LE(zeroAt - seen, 5e-3 + 1e-9);
    EXPECT_LE(hdc.statistics().maxOutputStep, parameters.forceRateLimit * parameters.servoPeriod + 1e-9);
}

}  // namespace

namespace {

// Found by fuzzing: the library reads a STATUS string with strlen, past the
// body when the string has no NUL. Such a body is refused before unpacking.
TEST(HapticLink, AStatusStringWithoutItsNulIsRefused)
{
    Bytes status = encodeStatus(kDeviceStatusName, kStatusOk, "simulated");
    ASSERT_EQ(status.back(), 0);
    status.back() = 'x';
    MessageReader reader(4096);
    reader.feed(status.data(), status.size());
    std::string error;
    EXPECT_FALSE(reader.next(error).has_value());
    EXPECT_NE(error.find("NUL"), std::string::npos) << error;
    EXPECT_FALSE(reader.fatal());
}

TEST(HapticLink, ASensorWhoseLengthDisagreesWithItsBodyIsRefused)
{
    Bytes load = encodeHandleLoad(HandleCommand{1.0, 0.0}, 1.0);
    load[58] = 9;  // claims 9 values in a body holding 2
    MessageReader reader(4096);
    reader.feed(load.data(), load.size());
    std::string error;
    EXPECT_FALSE(reader.next(error).has_value());
    EXPECT_NE(error.find("does not match its length"), std::string::npos) << error;
}

}  // namespace
