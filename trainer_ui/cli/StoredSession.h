#pragma once
/// \file
/// A finished procedure as the records store it: the compressed input trace,
/// the encoded recording, the simulated duration and the events. Scores,
/// metrics and progress are added by scoreInto (RecordsAccess.h).

#include "db/Records.h"
#include "simcore/procedure/ProcedureLoop.h"

namespace colonosim::cli {

[[nodiscard]] db::SessionResult storedSession(const procedure::ProcedureLoop& loop);

}  // namespace colonosim::cli
