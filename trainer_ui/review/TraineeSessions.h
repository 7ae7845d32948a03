#pragma once
/// \file
/// The completed sessions of each trainee, read from the records once and
/// shared by the instructor's pages (trainees, curves, sessions, comparison):
/// with 10,000 sessions one read takes about a third of a second, so each
/// page reading its own would multiply the wait. clear() forgets them all
/// (InstructorHome::refresh).

#include "db/Records.h"

#include <map>
#include <string>
#include <vector>

namespace colonosim::app {

class TraineeSessions {
public:
    TraineeSessions(db::Records& records, const db::Actor& actor) : m_records(records), m_actor(actor) {}

    /// Throws db::AccessDenied when the actor may not read the trainee.
    [[nodiscard]] const std::vector<db::SessionRow>& of(const std::string& trainee)
    {
        auto it = m_sessions.find(trainee);
        if (it == m_sessions.end()) {
            it = m_sessions.emplace(trainee, m_records.sessions(m_actor, trainee)).first;
        }
        return it->second;
    }
    void clear() { m_sessions.clear(); }

private:
    db::Records& m_records;
    db::Actor m_actor;
    std::map<std::string, std::vector<db::SessionRow>> m_sessions;
};

}  // namespace colonosim::app
