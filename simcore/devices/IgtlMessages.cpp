#include "simcore/devices/IgtlMessages.h"

#include <igtlMessageHeader.h>
#include <igtlSensorMessage.h>
#include <igtlStatusMessage.h>
#include <igtlTimeStamp.h>
#include <igtlTransformMessage.h>
#include <igtl_header.h>

#include <cmath>
#include <cstring>

namespace colonosim::devices {

namespace {
constexpr double kMillimetre = 1e-3;

void stamp(igtl::MessageBase* message, double time)
{
    igtl::TimeStamp::Pointer ts = igtl::TimeStamp::New();
    ts->SetTime(time);
    message->SetTimeStamp(ts);
}

void append(Bytes& out, igtl::MessageBase* message)
{
    message->Pack();
    const auto* p = static_cast<const std::uint8_t*>(message->GetPackPointer());
    out.insert(out.end(), p, p + message->GetPackSize());
}

Bytes sensor(const char* name, const double* values, unsigned n, double time)
{
    igtl::SensorMessage::Pointer m = igtl::SensorMessage::New();
    m->SetDeviceName(name);
    m->SetLength(n);
    for (unsigned i = 0; i < n; ++i) {
        m->SetValue(i, values[i]);
    }
    stamp(m, time);
    Bytes out;
    append(out, m);
    return out;
}

std::string describe(const char* field, double value, const params::ParameterSpec& spec)
{
    params::ParameterSpec named = spec;
    named.name = field;
    return params::describeRejection("igtl", named, value);
}
}  // namespace

Bytes encodeInput(const procedure::InputSample& input, double time)
{
    Bytes out;
    igtl::TransformMessage::Pointer pose = igtl::TransformMessage::New();
    pose->SetDeviceName(kPoseName);
    igtl::Matrix4x4 m;
    igtl::IdentityMatrix(m);
    const auto c = static_cast<float>(std::cos(input.rotation));
    const auto s = static_cast<float>(std::sin(input.rotation));
    m[0][0] = c;
    m[0][1] = -s;
    m[1][0] = s;
    m[1][1] = c;
    m[2][3] = static_cast<float>(input.insertion / kMillimetre);
    pose->SetMatrix(m);
    stamp(pose, time);
    append(out, pose);
    const double angles[3] = {input.rotation, input.dialUpDown, input.dialLeftRight};
    const Bytes a = sensor(kAnglesName, angles, 3, time);
    out.insert(out.end(), a.begin(), a.end());
    const double buttons[1] = {static_cast<double>(input.buttons)};
    const Bytes b = sensor(kButtonsName, buttons, 1, time);
    out.insert(out.end(), b.begin(), b.end());
    return out;
}

Bytes encodeHandleLoad(const HandleCommand& load, double simulatorTime)
{
    const double values[2] = {load.force, load.torque};
    return sensor(kHandleLoadName, values, 2, simulatorTime);
}

Bytes encodeStatus(const std::string& deviceName, int code, const std::string& text)
{
    igtl::StatusMessage::Pointer m = igtl::StatusMessage::New();
    m->SetDeviceName(deviceName.c_str());
    m->SetCode(code);
    m->SetSubCode(0);
    m->SetErrorName(code == kStatusOk ? "OK" : "ERROR");
    m->SetStatusString(text.c_str());
    Bytes out;
    append(out, m);
    return out;
}

void MessageReader::feed(const std::uint8_t* data, std::size_t size)
{
    if (m_start > 0 && m_start == m_buffer.size()) {
        m_buffer.clear();
        m_start = 0;
    }
    m_buffer.insert(m_buffer.end(), data, data + size);
}

std::optional<Message> MessageReader::next(std::string& error)
{
    error.clear();
    constexpr std::size_t kHeader = IGTL_HEADER_SIZE;
    while (!m_fatal && m_buffer.size() - m_start >= kHeader) {
        igtl::MessageHeader::Pointer header = igtl::MessageHeader::New();
        header->InitPack();
        std::memcpy(header->GetPackPointer(), m_buffer.data() + m_start, kHeader);
        header->Unpack();
        const int version = (m_buffer[m_start] << 8) | m_buffer[m_start + 1];  // big-endian uint16
        const auto body = static_cast<std::size_t>(header->GetBodySizeToRead());
        if (version < 1 || version > 2) {
            m_fatal = true;
            error =
                "igtl.header.version = " + std::to_string(version) + " is outside [1, 2]: not OpenIGTLink";
            return std::nullopt;
        }
        if (body > m_maxBody) {
            m_fatal = true;
            error = "igtl.header.bodySize = " + std::to_string(body) + " B is outside [0, " +
                    std::to_string(m_maxBody) + "] B (haptics.maxMessageBytes)";
            return std::nullopt;
        }
        if (m_buffer.size() - m_start < kHeader + body) {
            return std::nullopt;  // wait for the rest
        }
        const std::uint8_t* bodyBytes = m_buffer.data() + m_start + kHeader;
        m_start += kHeader + body;
        const std::string type = header->GetDeviceType();
        const std::string name = header->GetDeviceName();
        igtl::TimeStamp::Pointer ts = igtl::TimeStamp::New();
        header->GetTimeStamp(ts);
        Message out;
        out.time = ts->GetTimeStamp();
        auto unpack = [&](igtl::MessageBase* m) {
            m->SetMessageHeader(header);
            m->AllocatePack();
            std::memcpy(m->GetPackBodyPointer(), bodyBytes, body);
            return (m->Unpack(1) & igtl::MessageHeader::UNPACK_BODY) != 0;
        };
        auto refuse = [&](std::string why) {
            ++m_refused;
            error = why;
        };
        if (!std::isfinite(out.time)) {
            refuse("igtl." + name + ".timestamp is not finite");
            return std::nullopt;
        }
        // The library trusts a body's layout (a STATUS string without its NUL
        // is read past the body's end with strlen), so each body's layout is
        // checked here before the library unpacks it.
        constexpr std::size_t kTransformBody = 48;  // 12 float32
        constexpr std::size_t kSensorHeader = 10;   // length, status, unit
        constexpr std::size_t kStatusHeader = 30;   // code, subcode, error name
        const auto layoutError = [&]() -> std::string {
            if (type == "TRANSFORM" && body != kTransformBody) {
                return "igtl." + name + ": TRANSFORM body of " + std::to_string(body) + " B, not 48 B";
            }
            if (type == "SENSOR" && (body < kSensorHeader ||
                                     body != kSensorHeader + 8 * static_cast<std::size_t>(bodyBytes[0]))) {
                return "igtl." + name + ": SENSOR body of " + std::to_string(body) +
                       " B does not match its length";
            }
            if (type == "STATUS" && (body <= kStatusHeader || bodyBytes[body - 1] != 0)) {
                return "igtl." + name + ": STATUS body of " + std::to_string(body) +
                       " B without a NUL-terminated status string";
            }
            return {};
        };
        if (const std::string why = layoutError(); !why.empty()) {
            refuse(why);
            return std::nullopt;
        }
        if (type == "TRANSFORM" && name == kPoseName) {
            igtl::TransformMessage::Pointer m = igtl::TransformMessage::New();
            if (!unpack(m)) {
                refuse("igtl.ScopePose: body fails its CRC or is malformed");
                return std::nullopt;
            }
            igtl::Matrix4x4 matrix;
            m->GetMatrix(matrix);
            out.kind = Message::Kind::Pose;
            out.insertion = static_cast<double>(matrix[2][3]) * kMillimetre;
            if (!procedure::InputSample::insertionSpec.accepts(out.insertion)) {
                refuse(describe("ScopePose.insertion", out.insertion, procedure::InputSample::insertionSpec));
                return std::nullopt;
            }
            return out;
        }
        if (type == "SENSOR" && (name == kAnglesName || name == kButtonsName || name == kHandleLoadName)) {
            igtl::SensorMessage::Pointer m = igtl::SensorMessage::New();
            if (!unpack(m)) {
                refuse("igtl." + name + ": body fails its CRC or is malformed");
                return std::nullopt;
            }
            const unsigned want = name == kAnglesName ? 3U : name == kButtonsName ? 1U : 2U;
            if (m->GetLength() != want) {
                refuse("igtl." + name + ".length = " + std::to_string(m->GetLength()) + " is not " +
                       std::to_string(want));
                return std::nullopt;
            }
            for (unsigned i = 0; i < want; ++i) {
                out.values[i] = m->GetValue(i);
                if (!std::isfinite(out.values[i])) {
                    refuse("igtl." + name + "[" + std::to_string(i) + "] is not finite");
                    return std::nullopt;
                }
            }
            if (name == kAnglesName) {
                out.kind = Message::Kind::Angles;
                if (!procedure::InputSample::rotationSpec.accepts(out.values[0])) {
                    refuse(describe("ScopeAngles.rotation", out.values[0],
                                    procedure::InputSample::rotationSpec));
                    return std::nullopt;
                }
                for (int i = 1; i < 3; ++i) {
                    if (!procedure::InputSample::dialSpec.accepts(out.values[i])) {
                        refuse(describe(i == 1 ? "ScopeAngles.dialUpDown" : "ScopeAngles.dialLeftRight",
                                        out.values[i], procedure::InputSample::dialSpec));
                        return std::nullopt;
                    }
                }
            } else if (name == kButtonsName) {
                out.kind = Message::Kind::Buttons;
                const double bits = out.values[0];
                if (bits < 0.0 || bits > 15.0 || bits != std::floor(bits)) {
                    refuse("igtl.ScopeButtons = " + std::to_string(bits) +
                           " is outside the allowed range [0, 15] (integer bits)");
                    return std::nullopt;
                }
                out.buttons = static_cast<std::uint8_t>(bits);
            } else {
                out.kind = Message::Kind::HandleLoad;
            }
            return out;
        }
        if (type == "STATUS") {
            igtl::StatusMessage::Pointer m = igtl::StatusMessage::New();
            if (!unpack(m)) {
                refuse("igtl.STATUS: body fails its CRC or is malformed");
                return std::nullopt;
            }
            out.kind = Message::Kind::Status;
            out.statusCode = m->GetCode();
            out.statusText = m->GetStatusString();
            return out;
        }
        refuse("igtl: unexpected message " + type + " \"" + name + "\" (skipped)");
        return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace colonosim::devices
