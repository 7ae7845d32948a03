#include "simcore/physics/ActiveRegion.h"

namespace colonosim::physics {

ActiveRegion::ActiveRegion(std::vector<std::vector<int>> neighbours, const SleepParameters& parameters)
    : m_neighbours(std::move(neighbours)), m_parameters(parameters)
{
    params::require("sleep", SleepParameters::sleepSpeedSpec, parameters.sleepSpeed);
    params::require("sleep", SleepParameters::wakeSpeedSpec, parameters.wakeSpeed);
    params::require("sleep", SleepParameters::quietTimeSpec, parameters.quietTime);
    if (parameters.wakeHops < 1 || parameters.wakeHops > 20) {
        throw params::ParameterError("sleep.wakeHops = " + std::to_string(parameters.wakeHops) +
                                     " is outside the allowed range [1, 20]");
    }
    m_quiet.assign(m_neighbours.size(), 0.0);
    m_hop.assign(m_neighbours.size(), -1);
    m_numAwake = static_cast<int>(m_neighbours.size());
}

void ActiveRegion::update(TissueBody& body, double dt)
{
    const int n = body.numNodes();
    if (static_cast<int>(m_quiet.size()) != n) {
        m_quiet.assign(static_cast<size_t>(n), 0.0);
        m_hop.assign(static_cast<size_t>(n), -1);
        m_neighbours.resize(static_cast<size_t>(n));
    }
    m_flags = body.awake();
    bool changed = false;
    const double sleep2 = m_parameters.sleepSpeed * m_parameters.sleepSpeed;
    const double wake2 = m_parameters.wakeSpeed * m_parameters.wakeSpeed;
    const Velocities& v = body.velocities();

    // Wake: breadth-first from every fast node, up to wakeHops hops.
    m_frontier.clear();
    for (const int i : body.integratedNodes()) {
        if (v.col(i).squaredNorm() > wake2) {
            m_frontier.push_back(i);
            m_hop[static_cast<size_t>(i)] = 0;
        }
    }
    m_touched = m_frontier;
    std::vector<int>& touched = m_touched;
    for (int hop = 1; hop <= m_parameters.wakeHops && !m_frontier.empty(); ++hop) {
        m_next.clear();
        for (const int i : m_frontier) {
            for (const int j : m_neighbours[static_cast<size_t>(i)]) {
                if (m_hop[static_cast<size_t>(j)] >= 0) {
                    continue;
                }
                m_hop[static_cast<size_t>(j)] = hop;
                touched.push_back(j);
                m_next.push_back(j);
                m_quiet[static_cast<size_t>(j)] = 0.0;
                if (m_flags[static_cast<size_t>(j)] == 0) {
                    m_flags[static_cast<size_t>(j)] = 1;
                    changed = true;
                }
            }
        }
        m_frontier.swap(m_next);
    }
    for (const int i : touched) {
        m_hop[static_cast<size_t>(i)] = -1;
    }

    // Sleep: nodes slow for quietTime.
    for (const int i : body.integratedNodes()) {
        double& quiet = m_quiet[static_cast<size_t>(i)];
        quiet = v.col(i).squaredNorm() < sleep2 ? quiet + dt : 0.0;
        if (quiet >= m_parameters.quietTime && !body.isHeldAwake(i)) {
            m_flags[static_cast<size_t>(i)] = 0;
            changed = true;
        }
    }
    if (changed) {
        body.setAwake(m_flags);
    }
    m_numAwake = 0;
    for (const std::uint8_t flag : body.awake()) {
        m_numAwake += flag;
    }
}

}  // namespace colonosim::physics
