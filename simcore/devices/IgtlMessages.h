#pragma once
/// \file
/// The OpenIGTLink (version 2 framing) mapping between the Haptic Device
/// Controller and the simulator. Framing, CRC and byte order are the
/// library's (libopenigtlink); this file only says which standard message
/// carries what, and checks every value that arrives.
///
/// HDC -> simulator, one frame per servo tick, all three with the tick's time:
///   TRANSFORM "ScopePose"    insertion as translation (0, 0, z) in mm (the
///                            IGTL convention), shaft rotation as Rz(angle)
///                            (what 3D Slicer or PLUS can display directly);
///   SENSOR    "ScopeAngles"  [shaft rotation (multi-turn), dial up/down,
///                            dial left/right] in rad (a matrix cannot hold turns);
///   SENSOR    "ScopeButtons" [button bits] (air 1, water 2, suction 4, mark 8).
///   STATUS    "DeviceStatus" OK, or code DISABLED with "emergency stop".
/// Simulator -> HDC, once per simulator step:
///   SENSOR    "HandleLoad"   [axial force N (+ resists insertion), torque N m],
///                            stamped with the simulator's time;
///   STATUS    "Simulator"    refusals (e.g. "busy: another HDC is connected").

#include "simcore/devices/ForceServo.h"
#include "simcore/procedure/DeviceInput.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace colonosim::devices {

using Bytes = std::vector<std::uint8_t>;

inline constexpr const char* kPoseName = "ScopePose";
inline constexpr const char* kAnglesName = "ScopeAngles";
inline constexpr const char* kButtonsName = "ScopeButtons";
inline constexpr const char* kDeviceStatusName = "DeviceStatus";
inline constexpr const char* kHandleLoadName = "HandleLoad";
inline constexpr const char* kSimulatorStatusName = "Simulator";

/// STATUS codes used (the standard's values).
inline constexpr int kStatusOk = 1;
inline constexpr int kStatusDisabled = 11;
inline constexpr int kStatusBusy = 13;  ///< "device busy"

/// One input frame of the device (three messages).
[[nodiscard]] Bytes encodeInput(const procedure::InputSample& input, double time);
[[nodiscard]] Bytes encodeHandleLoad(const HandleCommand& load, double simulatorTime);
[[nodiscard]] Bytes encodeStatus(const std::string& deviceName, int code, const std::string& text);

/// One message that arrived, checked.
struct Message {
    enum class Kind { Pose, Angles, Buttons, HandleLoad, Status };
    Kind kind = Kind::Status;
    double time = 0.0;             ///< the header's time stamp, s
    double insertion = 0.0;        ///< Pose: m
    double values[3] = {0, 0, 0};  ///< Angles: rad; HandleLoad: N, N m
    std::uint8_t buttons = 0;      ///< Buttons
    int statusCode = 0;            ///< Status
    std::string statusText;        ///< Status
};

/// Splits a byte stream into messages. A message that is malformed, fails
/// its CRC, is of an unexpected type or carries a value outside its range is
/// refused with a reason and skipped (the stream stays in step). A header
/// that announces a body above the limit, or is not OpenIGTLink at all,
/// makes the stream unusable: fatal() is then true and the link must close.
class MessageReader {
public:
    explicit MessageReader(std::size_t maxBodyBytes) : m_maxBody(maxBodyBytes) {}

    void feed(const std::uint8_t* data, std::size_t size);
    /// The next complete message, or nothing. Refusals go to `error`.
    std::optional<Message> next(std::string& error);

    [[nodiscard]] bool fatal() const { return m_fatal; }
    [[nodiscard]] int refused() const { return m_refused; }

private:
    std::size_t m_maxBody;
    Bytes m_buffer;
    std::size_t m_start = 0;
    bool m_fatal = false;
    int m_refused = 0;
};

}  // namespace colonosim::devices
