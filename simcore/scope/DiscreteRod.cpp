#include "simcore/scope/DiscreteRod.h"

#include "simcore/scope/Rotation.h"

#include <algorithm>

namespace colonosim::scope {

void DiscreteRod::reset(int numNodes, double length, double flexuralRigidity, double torsionalRigidity,
                        int capacity)
{
    const auto cap = static_cast<size_t>(std::max(capacity, numNodes));
    for (auto* v : {&theta, &force, &torque, &position, &damping, &thetaStart}) {
        v->reserve(cap);
        v->assign(static_cast<size_t>(numNodes), Eigen::Vector3d::Zero());
    }
    for (auto* m : {&dial, &frame}) {
        m->reserve(cap);
        m->assign(static_cast<size_t>(numNodes), Eigen::Matrix3d::Identity());
    }
    hasDial.reserve(cap);
    hasDial.assign(static_cast<size_t>(numNodes), 0);
    elementLength = numNodes > 1 ? length / (numNodes - 1) : length;
    stiffness = Eigen::Vector3d(flexuralRigidity, flexuralRigidity, torsionalRigidity) / elementLength;
    rebuild();
}

Eigen::Vector3d DiscreteRod::jointStiffness(int joint) const
{
    if (joint == numNodes() - 1) {
        return 2.0 * stiffness;  // the tip half-joint (also when it is the only one)
    }
    if (joint == 0) {
        // The clamp joint stands for the stub and half of element 0.
        return stiffness * (elementLength / (stubLength + 0.5 * elementLength));
    }
    return stiffness;
}

const Eigen::Matrix3d& DiscreteRod::frameBefore(int joint) const
{
    return joint == 0 ? baseFrame : frame[static_cast<size_t>(joint - 1)];
}

void DiscreteRod::resizeAtBase(int numNodes)
{
    const int old = this->numNodes();
    const auto n = static_cast<size_t>(numNodes);
    if (numNodes > old) {
        const auto added = static_cast<size_t>(numNodes - old);
        theta.resize(n);
        std::copy_backward(theta.begin(), theta.begin() + old, theta.end());
        std::fill(theta.begin(), theta.begin() + static_cast<std::ptrdiff_t>(added), Eigen::Vector3d::Zero());
    } else if (numNodes < old) {
        // The joints that leave at the base pass their rotation on to the new
        // first joint, so every element that stays keeps its direction (the
        // stays are translated by at most l |Theta_0|, not turned about the
        // clamp by the dropped angles).
        const auto dropped = static_cast<size_t>(old - numNodes);
        Eigen::Matrix3d carried = Eigen::Matrix3d::Identity();
        for (size_t k = 0; k <= dropped; ++k) {
            carried =
                carried * (hasDial[k] ? dial[k] : Eigen::Matrix3d::Identity()) * rotationFromVector(theta[k]);
        }
        theta[dropped] = vectorFromRotation(carried);
        std::copy(theta.begin() + (old - numNodes), theta.end(), theta.begin());
        theta.resize(n);
    }
    dial.assign(n, Eigen::Matrix3d::Identity());
    hasDial.assign(n, 0);
    force.assign(n, Eigen::Vector3d::Zero());
    torque.assign(n, Eigen::Vector3d::Zero());
    damping.assign(n, Eigen::Vector3d::Zero());
    thetaStart = theta;
    position.resize(n);
    frame.resize(n);
    rebuild();
}

void DiscreteRod::rebuild()
{
    const int n = numNodes();
    Eigen::Vector3d x = basePosition + stubLength * baseFrame.col(2);
    const Eigen::Matrix3d* before = &baseFrame;
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<size_t>(k);
        position[i] = x;
        const Eigen::Matrix3d r = rotationFromVector(theta[i]);
        frame[i].noalias() = hasDial[i] ? Eigen::Matrix3d(*before * dial[i]) * r : *before * r;
        x += elementLength * frame[i].col(2);
        before = &frame[i];
    }
}

void DiscreteRod::clearLoads()
{
    std::fill(force.begin(), force.end(), Eigen::Vector3d::Zero());
    std::fill(torque.begin(), torque.end(), Eigen::Vector3d::Zero());
}

}  // namespace colonosim::scope
