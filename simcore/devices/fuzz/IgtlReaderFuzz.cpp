// libFuzzer target of the HDC link's receiving side: arbitrary bytes, cut
// into arbitrary chunks, go through the OpenIGTLink reader, and every
// message it accepts goes to a force servo. Fails (aborts) on a crash, a
// sanitizer report, an accepted message with a non-finite or out-of-range
// value, or a servo output beyond the device limits or the rate limit.
#include "simcore/devices/ForceServo.h"
#include "simcore/devices/IgtlMessages.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>

using namespace colonosim::devices;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const HapticParameters parameters;
    MessageReader reader(static_cast<std::size_t>(parameters.maxMessageBytes));
    ForceServo servo(parameters);
    double now = 0.0;
    std::size_t at = 0;
    while (at < size && !reader.fatal()) {
        const std::size_t chunk = 1 + data[at] % 97;  // the first byte of each chunk sets its length
        const std::size_t take = std::min(chunk, size - at);
        reader.feed(data + at, take);
        at += take;
        std::string error;
        for (;;) {
            const std::optional<Message> m = reader.next(error);
            if (!m) {
                if (error.empty() || reader.fatal()) {
                    break;
                }
                continue;
            }
            if (!std::isfinite(m->time) || !std::isfinite(m->insertion) || !std::isfinite(m->values[0]) ||
                !std::isfinite(m->values[1]) || !std::isfinite(m->values[2]) || m->buttons > 15) {
                std::abort();
            }
            if (m->kind == Message::Kind::HandleLoad) {
                servo.receive(HandleCommand{m->values[0], m->values[1]}, m->time, now);
            }
        }
        now += parameters.servoPeriod;
        const double before = servo.output().force;
        const HandleCommand& out = servo.tick(now);
        if (!std::isfinite(out.force) || std::abs(out.force) > parameters.maxForce ||
            std::abs(out.torque) > parameters.maxTorque ||
            std::abs(out.force - before) >
                parameters.forceRateLimit * parameters.servoPeriod * (1.0 + 1e-9)) {
            std::abort();
        }
    }
    return 0;
}
