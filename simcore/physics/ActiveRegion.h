#pragma once
/// \file
/// Model only what a scene needs: nodes far from every load and at rest
/// sleep and are not integrated (their springs are skipped when both ends
/// sleep). A node falls asleep after its speed has stayed below sleepSpeed
/// for quietTime; it wakes when a node within wakeHops spring hops moves
/// faster than wakeSpeed, or when an external force is applied to it.

#include "simcore/params/Parameter.h"
#include "simcore/physics/TissueBody.h"

#include <vector>

namespace colonosim::physics {

struct SleepParameters {
    static constexpr params::ParameterSpec sleepSpeedSpec{
        "sleepSpeed",
        "m/s",
        2e-4,
        1e-6,
        1e-1,
        "speed below which a node may fall asleep",
        "model choice; the bench reports the error it costs against the full simulation"};
    static constexpr params::ParameterSpec wakeSpeedSpec{"wakeSpeed",
                                                         "m/s",
                                                         1e-3,
                                                         1e-6,
                                                         1.0,
                                                         "speed of a nearby node that wakes a sleeping one",
                                                         "model choice; see sleepSpeed"};
    static constexpr params::ParameterSpec quietTimeSpec{"quietTime",
                                                         "s",
                                                         0.05,
                                                         1e-3,
                                                         10.0,
                                                         "time a node must stay slow before sleeping",
                                                         "model choice; see sleepSpeed"};

    double sleepSpeed = sleepSpeedSpec.defaultValue;
    double wakeSpeed = wakeSpeedSpec.defaultValue;
    double quietTime = quietTimeSpec.defaultValue;
    int wakeHops = 3;  ///< spring hops over which a moving node wakes its neighbourhood
};

class ActiveRegion {
public:
    /// `neighbours`: spring-connected nodes of each node. Throws ParameterError
    /// for parameters outside their declared ranges.
    ActiveRegion(std::vector<std::vector<int>> neighbours, const SleepParameters& parameters);

    /// Called once per loop step of length dt (s).
    void update(TissueBody& body, double dt);
    [[nodiscard]] int numAwake() const { return m_numAwake; }

private:
    std::vector<std::vector<int>> m_neighbours;
    SleepParameters m_parameters;
    std::vector<double> m_quiet;
    std::vector<std::uint8_t> m_flags;
    std::vector<int> m_frontier;
    std::vector<int> m_next;
    std::vector<int> m_hop;
    std::vector<int> m_touched;
    int m_numAwake = 0;
};

}  // namespace colonosim::physics
