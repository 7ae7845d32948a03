#include "trainer_ui/cli/StoredSession.h"

#include "db/RecordingCodec.h"
#include "db/StoredTrace.h"

#include <string>

namespace colonosim::cli {

namespace {
QByteArray bytes(const std::vector<char>& v)
{
    return QByteArray(v.data(), static_cast<qsizetype>(v.size()));
}
}  // namespace

db::SessionResult storedSession(const procedure::ProcedureLoop& loop)
{
    db::SessionResult result;
    result.trace = bytes(db::encodeStoredTrace(loop.trace()));
    result.recording = bytes(db::encodeRecording(loop.recording()));
    result.duration = loop.time();
    for (const auto& e : loop.recording().events) {
        result.events.push_back({e.time, std::string(procedure::eventName(e.kind)), e.detail});
    }
    return result;
}

}  // namespace colonosim::cli
