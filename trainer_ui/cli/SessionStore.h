#pragma once
/// \file
/// Storing a finished procedure in the records, the one path shared by
/// `colonosim run --user` and the trainer's procedure screen: the stored
/// trace (lossless, for replay), the recording, the events, the metrics
/// scored against the task's benchmark set and the user's progress, written
/// in one transaction onto the session row that beginSession inserted as
/// running before the first step.

#include "db/Records.h"
#include "scoring/SessionMetrics.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <string>

namespace colonosim::cli {

/// The curriculum task `id` of the core curriculum, checked to be runnable;
/// UsageError naming the value and the runnable tasks otherwise.
std::string checkTask(const std::string& id);

/// A finished procedure as the records store it: `loop`'s compressed input
/// trace and simulated duration, and `recording` (the loop's, with the
/// renderer's lesion events merged in when it watched: recordingSeenBy,
/// SessionCoverage.h), encoded and as events (scores, metrics and progress
/// are added by scoreInto, RecordsAccess.h).
[[nodiscard]] db::SessionResult storedSession(const procedure::ProcedureLoop& loop,
                                              const procedure::Recording& recording);

/// Scores `recording` of `loop` for `task` and completes `session` of
/// `actor`. Returns what was stored (metrics, scores, progress).
db::SessionResult completeStoredSession(db::Records& records, const db::Actor& actor, qint64 session,
                                        const std::string& task, const procedure::ProcedureLoop& loop,
                                        const procedure::Recording& recording,
                                        const scoring::ScoringContext& context);

}  // namespace colonosim::cli
