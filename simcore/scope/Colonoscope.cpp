#include "simcore/scope/Colonoscope.h"

#include "simcore/scope/Rotation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

namespace colonosim::scope {

namespace {

void refuse(const std::string& what, double value, const std::string& range)
{
    throw params::ParameterError(
        "scope." + what + " = " + std::to_string(value) +
        (std::isfinite(value) ? " is outside the allowed range " : " is not finite; range ") + range);
}

void requireFinite(const std::string& what, const Eigen::Vector3d& v)
{
    if (!v.allFinite()) {
        throw params::ParameterError("scope." + what + " is not finite");
    }
}

constexpr int kGuardRetries = 3;           ///< solves the step guard may refuse in one step()
constexpr double kGuardDampingGain = 4.0;  ///< what each refusal multiplies the joints' damping by

}  // namespace

Colonoscope::Colonoscope(const ScopeParameters& parameters) : m_parameters(parameters)
{
    m_parameters.validate();
    const int numNodes = static_cast<int>(m_parameters.numNodes);
    m_materialElementLength = m_parameters.workingLength / (numNodes - 1);
    m_rod.reset(numNodes, m_parameters.workingLength, m_parameters.flexuralRigidity,
                m_parameters.torsionalRigidity, numNodes);
    m_rod.resizeAtBase(1);
    updateBase();
}

void Colonoscope::setHandlePose(const Eigen::Vector3d& anus, const Eigen::Vector3d& direction,
                                const Eigen::Vector3d& up)
{
    requireFinite("handle anus position", anus);
    requireFinite("handle insertion direction", direction);
    requireFinite("handle up", up);
    const Eigen::Vector3d forward = direction.normalized();
    const Eigen::Vector3d upOrtho = up - up.dot(forward) * forward;
    if (direction.norm() < 1e-12 || upOrtho.norm() < 1e-6 * up.norm() || up.norm() < 1e-12) {
        throw params::ParameterError(
            "scope.handle: insertion direction must be non-zero and 'up' not parallel to it");
    }
    m_anus = anus;
    m_entryFrame.col(2) = forward;
    m_entryFrame.col(1) = upOrtho.normalized();
    m_entryFrame.col(0) = m_entryFrame.col(1).cross(forward);
    updateBase();
}

void Colonoscope::setInsertion(double length)
{
    if (!(length >= 0.0 && length <= m_parameters.workingLength)) {
        refuse("insertion", length, "[0, " + std::to_string(m_parameters.workingLength) + "] m");
    }
    m_insertion = length;
    const int maxNodes = static_cast<int>(m_parameters.numNodes);
    const int n =
        std::min(maxNodes, static_cast<int>(std::floor(length / m_materialElementLength + 1e-9)) + 1);
    if (n != m_rod.numNodes()) {
        m_rod.resizeAtBase(n);
    }
    updateBase();
}

void Colonoscope::setShaftRotation(double angle)
{
    if (!(std::abs(angle) <= 1000.0)) {
        refuse("shaftRotation", angle, "[-1000, 1000] rad");
    }
    m_shaftRotation = angle;
    updateBase();
}

void Colonoscope::setDials(double upDown, double leftRight)
{
    const double limit = 2.0 * std::numbers::pi;
    if (!(std::abs(upDown) <= limit)) {
        refuse("upDownDial", upDown, "[-2 pi, 2 pi] rad (clamped to the clinical limit)");
    }
    if (!(std::abs(leftRight) <= limit)) {
        refuse("leftRightDial", leftRight, "[-2 pi, 2 pi] rad (clamped to the clinical limit)");
    }
    m_upDown = std::clamp(upDown, -m_parameters.maxUpDownAngulation, m_parameters.maxUpDownAngulation);
    m_leftRight =
        std::clamp(leftRight, -m_parameters.maxLeftRightAngulation, m_parameters.maxLeftRightAngulation);
    updateDials();
    m_rod.rebuild();
}

void Colonoscope::setNodeForce(int node, const Eigen::Vector3d& force)
{
    m_rod.force[static_cast<size_t>(std::clamp(node, 0, m_rod.numNodes() - 1))] = force;
}

void Colonoscope::setNodeTorque(int node, const Eigen::Vector3d& torque)
{
    m_rod.torque[static_cast<size_t>(std::clamp(node, 0, m_rod.numNodes() - 1))] = torque;
}

void Colonoscope::addGravity(const Eigen::Vector3d& gravity)
{
    // Lumped masses: a full element per interior node, half at the tip, and
    // half plus the clamped stub at the base node: the weight of the inserted length.
    const double rho = m_parameters.linearMassDensity;
    const int n = m_rod.numNodes();
    for (int k = 0; k < n; ++k) {
        double length = m_materialElementLength;
        if (k == 0 || k == n - 1) {
            length = n == 1 ? 0.0 : 0.5 * m_materialElementLength;
        }
        if (k == 0) {
            length += m_rod.stubLength;
        }
        m_rod.force[static_cast<size_t>(k)] += rho * length * gravity;
    }
}

void Colonoscope::beginStep(double dt, double dampingRatio)
{
    const int n = m_rod.numNodes();
    m_rod.thetaStart = m_rod.theta;
    m_rod.damping.assign(static_cast<size_t>(n), Eigen::Vector3d::Zero());
    m_guardRetries = 0;
    m_stepStart.clear();  // a quasi-static step has no damping to raise: unguarded
    if (!(dt > 0.0) || !(dampingRatio > 0.0)) {
        return;
    }
    m_stepStart = m_rod.position;
    const double element = m_rod.elementLength * m_parameters.linearMassDensity;
    double mass = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    double second = 0.0;
    for (int k = n - 1; k >= 0; --k) {
        const auto i = static_cast<size_t>(k);
        const Eigen::Vector3d& x = m_rod.position[i];
        const double inertia = std::max(0.0, second - 2.0 * x.dot(first) + x.squaredNorm() * mass);
        const Eigen::Vector3d k3 = m_rod.jointStiffness(k);
        m_rod.damping[i] = 2.0 * dampingRatio / dt * (k3 * inertia).cwiseSqrt();
        const double m = k == n - 1 ? 0.5 * element : element;
        mass += m;
        first += m * x;
        second += m * x.squaredNorm();
    }
}

void Colonoscope::step()
{
    const int iterations = static_cast<int>(m_parameters.solverIterations);
    if (m_stepStart.size() != m_rod.position.size()) {
        solveChain(m_rod, iterations, m_parameters.solverRelaxation);
        return;
    }
    m_thetaBefore = m_rod.theta;
    solveChain(m_rod, iterations, m_parameters.solverRelaxation);
    for (int retry = 0; retry < kGuardRetries && largestStepMotion() > m_parameters.maxNodeStep; ++retry) {
        m_rod.theta = m_thetaBefore;
        for (Eigen::Vector3d& d : m_rod.damping) {
            d *= kGuardDampingGain;
        }
        m_rod.rebuild();
        solveChain(m_rod, iterations, m_parameters.solverRelaxation);
        ++m_guardRetries;
    }
}

double Colonoscope::largestStepMotion() const
{
    double largest = 0.0;
    for (size_t i = 0; i < m_stepStart.size(); ++i) {
        largest = std::max(largest, (m_rod.position[i] - m_stepStart[i]).squaredNorm());
    }
    return std::sqrt(largest);
}

void Colonoscope::step(const std::function<void(DiscreteRod&)>& afterIteration)
{
    for (int it = 0; it < static_cast<int>(m_parameters.solverIterations); ++it) {
        solveChain(m_rod, 1, m_parameters.solverRelaxation);
        afterIteration(m_rod);
    }
}

TipPose Colonoscope::tipPose() const
{
    return {m_rod.position.back(), m_rod.frame.back()};
}

HandleLoad Colonoscope::handleLoad() const
{
    const BaseLoad base = baseLoad(m_rod);
    const Eigen::Vector3d axis = m_entryFrame.col(2);
    return {base.force, base.moment, base.force.dot(axis), -base.moment.dot(axis)};
}

void Colonoscope::updateBase()
{
    m_rod.basePosition = m_anus;
    // Counter-clockwise seen from the operator, who looks along the insertion
    // direction: a rotation about -z (a positive one about +z is clockwise,
    // as a right-handed screw turned clockwise advances).
    m_rod.baseFrame = m_entryFrame * rotationFromVector(Eigen::Vector3d(0.0, 0.0, -m_shaftRotation));
    m_rod.stubLength = std::max(0.0, m_insertion - (m_rod.numNodes() - 1) * m_materialElementLength);
    updateDials();
    m_rod.rebuild();
}

void Colonoscope::updateDials()
{
    const int n = m_rod.numNodes();
    const int section = std::max(
        1, static_cast<int>(std::lround(m_parameters.bendingSectionLength / m_materialElementLength)));
    // Up bends forward towards up: a negative rotation about x; left (the
    // viewer's left is +x, see TipPose): a positive one about up.
    const Eigen::Vector3d perJoint = Eigen::Vector3d(-m_upDown, m_leftRight, 0.0) / section;
    const bool active = perJoint.squaredNorm() > 0.0;
    const Eigen::Matrix3d rest = active ? rotationFromVector(perJoint) : Eigen::Matrix3d::Identity();
    // The joint at the clamp is entering the body: its share grows with the
    // inserted part of its element, so the bend inside is continuous in the
    // insertion (no jump of the tip when a node passes the anus).
    const double entering = std::clamp(m_rod.stubLength / m_materialElementLength, 0.0, 1.0);
    for (int k = 0; k < n; ++k) {
        const int fromTip = n - 1 - k;  // interior joints 1..section from the tip
        const bool inSection = active && fromTip >= 1 && fromTip <= section;
        const auto i = static_cast<size_t>(k);
        if (inSection && k == 0) {
            m_rod.dial[i] = rotationFromVector(entering * perJoint);
        } else {
            m_rod.dial[i] = inSection ? rest : Eigen::Matrix3d::Identity();
        }
        m_rod.hasDial[i] = inSection ? 1 : 0;
    }
}

}  // namespace colonosim::scope
