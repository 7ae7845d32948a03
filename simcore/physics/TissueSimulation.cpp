#include "simcore/physics/TissueSimulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace colonosim::physics {

namespace {
constexpr size_t kMaxStoredDiagnostics = 100;
/// Loop steps accepted at the first try after which a finer step that a
/// rejection imposed is relaxed by half (1 s at the 1 kHz loop): a passing
/// jolt, not the model, made the step fail.
constexpr long kRelaxAfter = 1000;
/// A retry at half the step whose offending speed is within this factor of
/// the first try's did not change it: the step resolves that motion (an
/// impulsive load), it is no instability of the step, and the finer step is
/// not kept.
constexpr double kSameSpeed = 1.1;
}  // namespace

TissueSimulation::TissueSimulation(TissueBody& body, const SteppingPolicy& policy)
    : m_body(body), m_policy(policy)
{
    params::require("stepping", SteppingPolicy::loopStepSpec, policy.loopStep);
    params::require("stepping", SteppingPolicy::safetySpec, policy.safetyFactor);
    params::require("stepping", SteppingPolicy::maxSpeedSpec, policy.maxNodeSpeed);
    if (policy.replanInterval < 1) {
        throw params::ParameterError("stepping.replanInterval = " + std::to_string(policy.replanInterval) +
                                     " must be >= 1 loop step");
    }
    if (policy.maxSubsteps < 1 || policy.maxSubsteps > 10000) {
        throw params::ParameterError("stepping.maxSubsteps = " + std::to_string(policy.maxSubsteps) +
                                     " is outside the allowed range [1, 10000]");
    }
    replan();
}

namespace {
bool within(double planned, double now, double tolerance)
{
    return std::abs(now - planned) <= tolerance * std::max(std::abs(planned), 1e-300);
}
}  // namespace

void TissueSimulation::refreshPlan()
{
    // The bound is re-evaluated at the current state; the plan (bisection for
    // the stable step, integrator, note) is re-derived only when the estimate
    // moved by more than 1%, which the safety factor covers.
    constexpr double kTolerance = 0.01;
    const StabilityEstimate now = estimateStability(m_body, m_kRow, m_cRow);
    m_stepsSincePlan = 0;
    if (within(m_stability.omegaMax, now.omegaMax, kTolerance) &&
        within(m_stability.dampingRateMax, now.dampingRateMax, kTolerance) &&
        within(m_stability.betaMin, now.betaMin, kTolerance) &&
        within(m_stability.betaMax, now.betaMax, kTolerance)) {
        return;
    }
    derivePlan(now);
}

void TissueSimulation::replan()
{
    derivePlan(estimateStability(m_body, m_kRow, m_cRow));
}

void TissueSimulation::derivePlan(const StabilityEstimate& estimate)
{
    m_stability = estimate;
    m_stableStep = maxStableStep(m_policy.integrator, m_stability);
    std::ostringstream note;
    m_stepsSincePlan = 0;
    if (m_policy.integrator == IntegratorKind::BackwardEuler || m_minimumSubsteps > m_policy.maxSubsteps) {
        if (m_integrator == nullptr || m_integrator->kind() != IntegratorKind::BackwardEuler) {
            m_integrator = makeIntegrator(IntegratorKind::BackwardEuler);
        }
        m_substeps = 1;
        note << "backward_euler, 1 step per loop step";
    } else {
        const double usable = m_policy.safetyFactor * m_stableStep;
        const double needed = usable > 0.0 ? std::ceil(m_policy.loopStep / usable) : INFINITY;
        if (needed <= m_policy.maxSubsteps) {
            if (m_integrator == nullptr || m_integrator->kind() != m_policy.integrator) {
                m_integrator = makeIntegrator(m_policy.integrator);
            }
            m_substeps = std::max(static_cast<int>(needed), m_minimumSubsteps);
            note << integratorName(m_policy.integrator) << ", " << m_substeps << " substeps (stable step "
                 << m_stableStep * 1e6 << " us, omega_max " << m_stability.omegaMax << " rad/s)";
        } else {
            if (m_integrator == nullptr || m_integrator->kind() != IntegratorKind::BackwardEuler) {
                m_integrator = makeIntegrator(IntegratorKind::BackwardEuler);
            }
            m_substeps = 1;
            note << integratorName(m_policy.integrator) << " would need " << needed
                 << " substeps (stable step " << m_stableStep * 1e6 << " us) > " << m_policy.maxSubsteps
                 << "; using backward_euler, 1 step per loop step";
        }
    }
    m_planNote = note.str();
}

bool TissueSimulation::checkState(StepDiagnostic& diagnostic) const
{
    const Positions& x = m_body.positions();
    const Velocities& v = m_body.velocities();
    const double limit2 = m_policy.maxNodeSpeed * m_policy.maxNodeSpeed;
    for (const int i : m_body.integratedNodes()) {
        const double speed2 = v.col(i).squaredNorm();
        if (!x.col(i).allFinite() || !std::isfinite(speed2)) {
            diagnostic.node = i;
            diagnostic.speed = std::numeric_limits<double>::infinity();
            diagnostic.message = "node " + std::to_string(i) + " has a non-finite position or velocity";
            return false;
        }
        if (speed2 > limit2) {
            std::ostringstream out;
            out << "node " << i << " speed " << std::sqrt(speed2) << " m/s exceeds maxNodeSpeed "
                << m_policy.maxNodeSpeed << " m/s";
            diagnostic.node = i;
            diagnostic.speed = std::sqrt(speed2);
            diagnostic.message = out.str();
            return false;
        }
    }
    return true;
}

bool TissueSimulation::runSubsteps(int substeps, double& rejectedSpeed)
{
    const double h = m_policy.loopStep / substeps;
    for (int s = 0; s < substeps; ++s) {
        m_integrator->step(m_body, h);
    }
    // Organs are projected once per loop step: at the 0.5 m/s fastest wall
    // speed a node penetrates at most 0.5 mm within one 1 ms step.
    m_body.projectConstraints(m_body.positions(), m_body.velocities());
    StepDiagnostic diagnostic;
    if (checkState(diagnostic)) {
        return true;
    }
    ++m_rejectedSteps;
    rejectedSpeed = diagnostic.speed;
    if (m_rejections.size() < kMaxStoredDiagnostics) {
        diagnostic.time = m_time;
        std::ostringstream out;
        out << "t = " << m_time << " s: step rejected (" << integratorName(m_integrator->kind()) << ", "
            << substeps << " substeps of " << h * 1e6 << " us): " << diagnostic.message;
        diagnostic.message = out.str();
        m_rejections.push_back(diagnostic);
    }
    return false;
}

void TissueSimulation::restoreSaved()
{
    m_body.positions() = m_savedX;
    m_body.velocities() = m_savedV;
}

bool TissueSimulation::advance()
{
    m_savedX = m_body.positions();
    m_savedV = m_body.velocities();
    double firstSpeed = 0.0;  // m/s of the node that failed each try
    double retrySpeed = 0.0;
    bool accepted = runSubsteps(m_substeps, firstSpeed);
    if (!accepted) {
        // Keep the finer step and re-derive the plan from the current state;
        // past the budget this switches to backward Euler.
        restoreSaved();
        const int minimumBefore = m_minimumSubsteps;
        m_minimumSubsteps = 2 * m_substeps;
        m_goodSinceRejection = 0;
        replan();
        accepted = runSubsteps(m_substeps, retrySpeed);
        if (!accepted && std::isfinite(firstSpeed) && retrySpeed < kSameSpeed * firstSpeed &&
            retrySpeed > firstSpeed / kSameSpeed) {
            // Halving the step changed nothing: the step resolves that motion
            // (an impulsive load), it is no instability. Keep the plan and
            // the retried state: rejecting it froze the colon for good under
            // a load that stays (a scope jammed at full dials, 1.358 s into
            // ProcedureLoop.FullDialsWhileJammedStayStable).
            m_minimumSubsteps = minimumBefore;
            replan();
            accepted = true;
        } else if (!accepted) {
            restoreSaved();
        }
    } else if (m_minimumSubsteps > 1 && ++m_goodSinceRejection >= kRelaxAfter) {
        m_minimumSubsteps = std::max(1, m_minimumSubsteps / 2);
        m_goodSinceRejection = 0;
        replan();
    } else if (++m_stepsSincePlan >= m_policy.replanInterval) {
        refreshPlan();
    }
    if (accepted) {
        m_time += m_policy.loopStep;
        if (m_region != nullptr) {
            m_region->update(m_body, m_policy.loopStep);
        }
    }
    return accepted;
}

}  // namespace colonosim::physics
