// The haptic link's costs: OpenIGTLink framing of one input frame and one
// load (encode, decode with CRC), and the pose-to-force round trip over
// loopback through the simulator's HDC server and its device I/O thread,
// with a responder that answers each frame at once (the link alone,
// without the simulator's step). Run: build/bench/bench_haptics
#include "simcore/devices/HdcServer.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace {

using namespace colonosim::devices;

colonosim::procedure::InputSample sample()
{
    colonosim::procedure::InputSample s;
    s.insertion = 0.5;
    s.rotation = 1.0;
    s.dialUpDown = 0.3;
    return s;
}

void BM_EncodeInputFrame(benchmark::State& state)
{
    double t = 0.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(encodeInput(sample(), t += 1e-3));
    }
}
BENCHMARK(BM_EncodeInputFrame);

void BM_DecodeInputFrame(benchmark::State& state)
{
    const Bytes frame = encodeInput(sample(), 1.0);
    state.counters["frame_bytes"] = static_cast<double>(frame.size());
    for (auto _ : state) {
        MessageReader reader(4096);
        reader.feed(frame.data(), frame.size());
        std::string error;
        int n = 0;
        while (reader.next(error)) {
            ++n;
        }
        benchmark::DoNotOptimize(n);
    }
}
BENCHMARK(BM_DecodeInputFrame);

/// One input frame out, its load back, over loopback; the time is the round
/// trip. Counters give the p50 and p99 of the round trips, in microseconds.
void BM_LoopbackPoseToForce(benchmark::State& state)
{
    HdcServer server(0, HapticParameters{});
    std::atomic<bool> stop{false};
    std::thread responder([&] {
        while (!stop.load()) {
            if (auto in = server.latestInput()) {
                server.publishLoad(HandleCommand{1.0, 0.0}, in->time);
            }
            std::this_thread::yield();
        }
    });
    TcpLink link = TcpLink::connect("127.0.0.1", server.port(), 1.0);
    std::vector<double> trips;
    MessageReader reader(4096);
    Bytes bytes;
    double t = 0.0;
    for (auto _ : state) {
        t += 1e-3;
        const auto start = std::chrono::steady_clock::now();
        link.send(encodeInput(sample(), t));
        bool got = false;
        while (!got) {
            bytes.clear();
            link.receive(bytes, 0.01);
            reader.feed(bytes.data(), bytes.size());
            std::string error;
            while (auto m = reader.next(error)) {
                got = got || (m->kind == Message::Kind::HandleLoad && m->time >= t - 1e-6);
            }
        }
        trips.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    stop = true;
    responder.join();
    std::sort(trips.begin(), trips.end());
    if (!trips.empty()) {
        state.counters["p50_us"] = 1e6 * trips[trips.size() / 2];
        state.counters["p99_us"] = 1e6 * trips[std::min(trips.size() - 1, trips.size() * 99 / 100)];
        state.counters["max_us"] = 1e6 * trips.back();
    }
}
BENCHMARK(BM_LoopbackPoseToForce)->Iterations(5000)->UseRealTime();

}  // namespace
