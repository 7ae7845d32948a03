#include "trainer_ui/cli/SessionStore.h"

#include "curricula/Curriculum.h"
#include "db/RecordingCodec.h"
#include "db/StoredTrace.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/RecordsAccess.h"

namespace colonosim::cli {

namespace {
QByteArray bytes(const std::vector<char>& v)
{
    return QByteArray(v.data(), static_cast<qsizetype>(v.size()));
}
}  // namespace

std::string checkTask(const std::string& id)
{
    const auto curriculum =
        curricula::parseCurriculum(curricula::coreCurriculumXml(), "colonoscopy-core.xml");
    const curricula::Task* task = curriculum.value->find(id);
    std::string runnable;
    for (const curricula::Task& t : curriculum.value->tasks) {
        if (t.available) {
            runnable += (runnable.empty() ? "" : ", ") + t.id;
        }
    }
    if (!task) {
        throw UsageError("--task = " + id + " is not a task of colonoscopy-core (allowed: " + runnable + ")");
    }
    if (!task->available) {
        throw UsageError("--task = " + id + " cannot be run yet: " + task->unavailableReason +
                         " (allowed: " + runnable + ")");
    }
    return id;
}

db::SessionResult storedSession(const procedure::ProcedureLoop& loop, const procedure::Recording& recording)
{
    db::SessionResult result;
    result.trace = bytes(db::encodeStoredTrace(loop.trace()));
    result.recording = bytes(db::encodeRecording(recording));
    result.duration = loop.time();
    for (const auto& e : recording.events) {
        result.events.push_back({e.time, std::string(procedure::eventName(e.kind)), e.detail});
    }
    return result;
}

db::SessionResult completeStoredSession(db::Records& records, const db::Actor& actor, qint64 session,
                                        const std::string& task, const procedure::ProcedureLoop& loop,
                                        const procedure::Recording& recording,
                                        const scoring::ScoringContext& context)
{
    db::SessionResult result = storedSession(loop, recording);
    scoreInto(records, actor, task, scoring::computeMetrics(recording, context), result);
    records.completeSession(actor, session, result);
    return result;
}

}  // namespace colonosim::cli
