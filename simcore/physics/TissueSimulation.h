#pragma once
/// \file
/// Advances a tissue body by one fixed loop step (1 kHz by default; dt never
/// comes from the wall clock). From the model's stability bound it chooses
/// the number of substeps for an explicit integrator, or falls back to
/// backward Euler when the explicit step would need more substeps than the
/// budget allows, so that no parameter set in the declared ranges runs
/// unstable at the loop rate.
///
/// The body's positional constraints (organs) are applied once per loop step,
/// after the substeps. After each loop step the state is checked (finite, node speed below the
/// declared limit). A failing step is rejected: the last good state is kept,
/// a diagnostic names the node, the value and the limit, and the step is
/// retried once with twice the substeps, and the plan is re-derived from the
/// current state. The finer step is kept, but not for good: after 1 s of
/// steps accepted at the first try it is relaxed by half; and when the retry
/// fails on the same speed (within 10%), halving the step did not change the
/// motion (an impulsive load, not an unstable step): the finer step is not
/// kept and the retried state is taken (refusing it froze the colon for good
/// under a load that stays). The
/// bound is also re-evaluated at the current state every replanInterval loop
/// steps (large deformation changes the stiffness). advance() never throws.

#include "simcore/params/Parameter.h"
#include "simcore/physics/ActiveRegion.h"
#include "simcore/physics/Integrator.h"
#include "simcore/physics/StabilityBound.h"

#include <memory>
#include <string>
#include <vector>

namespace colonosim::physics {

struct SteppingPolicy {
    static constexpr params::ParameterSpec loopStepSpec{
        "loopStep",
        "s",
        1e-3,
        1e-5,
        1e-2,
        "fixed step of the procedure loop (1 kHz)",
        "haptic servo rate, reference/physical-parameters.md"};
    static constexpr params::ParameterSpec safetySpec{"safetyFactor",
                                                      "1",
                                                      0.9,
                                                      0.1,
                                                      1.0,
                                                      "fraction of the stable explicit step used",
                                                      "model choice: margin under the Gershgorin bound"};
    static constexpr params::ParameterSpec maxSpeedSpec{
        "maxNodeSpeed",
        "m/s",
        20.0,
        1.0,
        1000.0,
        "node speed above which a step is rejected as unstable",
        "model choice: 40x the 0.5 m/s fastest insertion"};

    IntegratorKind integrator = IntegratorKind::SymplecticEuler;
    double loopStep = loopStepSpec.defaultValue;
    double safetyFactor = safetySpec.defaultValue;
    double maxNodeSpeed = maxSpeedSpec.defaultValue;
    int maxSubsteps = 64;  ///< explicit substeps allowed per loop step before falling back to implicit
    int replanInterval =
        50;  ///< loop steps between re-evaluations of the stability bound at the current state
};

struct StepDiagnostic {
    double time = 0.0;  ///< s, start of the rejected loop step
    int node = -1;
    double speed = 0.0;  ///< m/s of that node (infinite when not finite)
    std::string message;
};

class TissueSimulation {
public:
    /// Refers to `body`, which must outlive the simulation. Throws
    /// ParameterError for a policy outside its declared ranges.
    TissueSimulation(TissueBody& body, const SteppingPolicy& policy);

    /// One loop step. Returns false when the step was rejected twice (on
    /// different speeds) and the last good state was kept.
    bool advance();

    /// Re-derives substeps and integrator from the current model (after a
    /// parameter or topology change).
    void replan();

    void setActiveRegion(ActiveRegion* region) { m_region = region; }

    [[nodiscard]] double time() const { return m_time; }
    [[nodiscard]] IntegratorKind integratorInUse() const { return m_integrator->kind(); }
    [[nodiscard]] int substeps() const { return m_substeps; }
    [[nodiscard]] double stableStep() const { return m_stableStep; }
    [[nodiscard]] const StabilityEstimate& stability() const { return m_stability; }
    [[nodiscard]] const std::string& planNote() const { return m_planNote; }
    [[nodiscard]] const std::vector<StepDiagnostic>& rejections() const { return m_rejections; }
    [[nodiscard]] long rejectedSteps() const { return m_rejectedSteps; }
    [[nodiscard]] Integrator& integrator() { return *m_integrator; }

private:
    /// Periodic: re-estimates, re-derives the plan only if the estimate moved.
    void refreshPlan();
    void derivePlan(const StabilityEstimate& estimate);
    /// One loop step in `substeps`; false when the state check rejected it,
    /// with the offending node's speed in `rejectedSpeed` (m/s); the body is
    /// left as the try ended (restoreSaved() puts the step's start back).
    bool runSubsteps(int substeps, double& rejectedSpeed);
    bool checkState(StepDiagnostic& diagnostic) const;
    void restoreSaved();

    TissueBody& m_body;
    SteppingPolicy m_policy;
    std::unique_ptr<Integrator> m_integrator;
    ActiveRegion* m_region = nullptr;
    StabilityEstimate m_stability;
    double m_stableStep = 0.0;
    int m_substeps = 1;
    double m_time = 0.0;
    std::string m_planNote;
    Eigen::VectorXd m_kRow, m_cRow;  ///< row-sum scratch of the stability estimate
    Positions m_savedX;
    Velocities m_savedV;
    std::vector<StepDiagnostic> m_rejections;
    long m_rejectedSteps = 0;
    long m_stepsSincePlan = 0;
    int m_minimumSubsteps = 1;      ///< raised after a rejection, halved again after kRelaxAfter good steps
    long m_goodSinceRejection = 0;  ///< loop steps accepted at the first try since the last rejection
};

}  // namespace colonosim::physics
