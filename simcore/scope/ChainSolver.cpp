#include "simcore/scope/ChainSolver.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace colonosim::scope {

namespace {

/// The rod's arrays as raw pointers: Eigen's vector stores may alias
/// anything, so the compiler would otherwise reload every std::vector's data
/// pointer after each store to theta.
struct ChainView {
    const Eigen::Vector3d* position;
    const Eigen::Matrix3d* frame;
    const Eigen::Vector3d* force;
    const Eigen::Vector3d* torque;
    const Eigen::Vector3d* damping;
    const Eigen::Vector3d* thetaStart;
    Eigen::Vector3d* theta;
};

ChainView viewOf(DiscreteRod& rod)
{
    return {rod.position.data(), rod.frame.data(),      rod.force.data(), rod.torque.data(),
            rod.damping.data(),  rod.thetaStart.data(), rod.theta.data()};
}

/// Eqs 2-5 at joint i under the moment m about its node (world frame):
/// Theta_i moves by w (C_i^T m - K Theta_i - D (Theta_i - Theta_start)) / (K + D).
/// Returns the largest |dTheta| component when `measure` is set, else 0.
inline double relaxJoint(const ChainView& rod, size_t i, const Eigen::Vector3d& m,
                         const Eigen::Vector3d& stiffness, double relaxation, bool measure)
{
    const Eigen::Vector3d& damping = rod.damping[i];
    Eigen::Vector3d& theta = rod.theta[i];
    Eigen::Vector3d net;
    net.noalias() = rod.frame[i].transpose() * m;
    net -= stiffness.cwiseProduct(theta);
    net -= damping.cwiseProduct(theta - rod.thetaStart[i]);
    const Eigen::Vector3d step = relaxation * net.cwiseQuotient(stiffness + damping);
    theta += step;  // eqs 4-5
    return measure ? step.cwiseAbs().maxCoeff() : 0.0;
}

/// Eq 1 from the tip to the base, and eqs 2-5 at each joint on the way.
/// Returns the largest |dTheta| when `measure` is set (the last iteration
/// only: the caller sees no other), else 0. The end joints are taken out of
/// the loop: their stiffness differs (jointStiffness()) and the tip's moment
/// has no lever arm yet.
double relaxJoints(DiscreteRod& rod, const Eigen::Vector3d& clampStiffness,
                   const Eigen::Vector3d& tipStiffness, double relaxation, bool measure)
{
    const ChainView view = viewOf(rod);
    const auto tip = static_cast<size_t>(rod.numNodes() - 1);
    Eigen::Vector3d m = view.torque[tip];
    double largest = std::max(0.0, relaxJoint(view, tip, m, tipStiffness, relaxation, measure));
    if (tip == 0) {
        return largest;
    }
    // Forces at the nodes downstream of i; summed from zero as before, so a
    // -0 in the tip force stays +0 here.
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    f += view.force[tip];
    for (size_t i = tip - 1; i > 0; --i) {
        m += (view.position[i + 1] - view.position[i]).cross(f);  // eq 1: moment about node i
        largest = std::max(largest, relaxJoint(view, i, m, rod.stiffness, relaxation, measure));
        f += view.force[i];
        m += view.torque[i];  // acts on element i - 1: upstream joints only
    }
    m += (view.position[1] - view.position[0]).cross(f);
    return std::max(largest, relaxJoint(view, 0, m, clampStiffness, relaxation, measure));
}

}  // namespace

double solveChain(DiscreteRod& rod, int iterations, double relaxation)
{
    // Neither end stiffness changes while the chain iterates.
    const Eigen::Vector3d clampStiffness = rod.jointStiffness(0);
    const Eigen::Vector3d tipStiffness = rod.jointStiffness(rod.numNodes() - 1);
    double largest = 0.0;
    for (int it = 0; it < iterations; ++it) {
        largest = relaxJoints(rod, clampStiffness, tipStiffness, relaxation, it == iterations - 1);
        rod.rebuild();  // eqs 6-7
    }
    return largest;
}

BaseLoad baseLoad(const DiscreteRod& rod)
{
    BaseLoad load;
    const int n = rod.numNodes();
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<size_t>(k);
        load.force += rod.force[i];
        load.moment += (rod.position[i] - rod.basePosition).cross(rod.force[i]) + rod.torque[i];
    }
    return load;
}

}  // namespace colonosim::scope
