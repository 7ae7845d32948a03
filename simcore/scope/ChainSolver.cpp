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
    const Eigen::Matrix3d* frame;
    const Eigen::Vector3d* force;
    const Eigen::Vector3d* torque;
    const Eigen::Vector3d* gain;
    const Eigen::Vector3d* pull;
    Eigen::Vector3d* theta;
};

ChainView viewOf(DiscreteRod& rod)
{
    return {rod.frame.data(),          rod.force.data(),       rod.torque.data(),
            rod.relaxationGain.data(), rod.dampingPull.data(), rod.theta.data()};
}

/// What eqs 2-5 need of each joint that does not change while the chain
/// iterates: the gain w / (K_k + D_k) and the damping's pull D_k Theta_start,k.
void prepareRelaxation(DiscreteRod& rod, double relaxation)
{
    const int n = rod.numNodes();
    rod.relaxationGain.resize(static_cast<size_t>(n));
    rod.dampingPull.resize(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<size_t>(k);
        rod.relaxationGain[i] = relaxation / rod.jointResistance(k).array();
        rod.dampingPull[i] = rod.damping[i].cwiseProduct(rod.thetaStart[i]);
    }
}

/// Eqs 2-5 at joint i under the moment m about its node (world frame):
/// Theta_i moves by w (C_i^T m - K Theta_i - D (Theta_i - Theta_start)) / (K + D),
/// computed as g (C_i^T m + D Theta_start) - w Theta_i with g = w / (K + D).
/// Returns the largest |dTheta| component when `measure` is set, else 0.
inline double relaxJoint(const ChainView& rod, size_t i, const Eigen::Vector3d& m, double relaxation,
                         bool measure)
{
    Eigen::Vector3d& theta = rod.theta[i];
    Eigen::Vector3d net;
    net.noalias() = rod.frame[i].transpose() * m;
    net += rod.pull[i];
    const Eigen::Vector3d step = rod.gain[i].cwiseProduct(net) - relaxation * theta;
    theta += step;  // eqs 4-5
    return measure ? step.cwiseAbs().maxCoeff() : 0.0;
}

/// Eq 1 from the tip to the base, and eqs 2-5 at each joint on the way.
/// Returns the largest |dTheta| when `measure` is set (the last iteration
/// only: the caller sees no other), else 0. The tip's moment has no lever
/// arm yet, and the clamp's takes the last element's.
double relaxJoints(DiscreteRod& rod, double relaxation, bool measure)
{
    const ChainView view = viewOf(rod);
    const double length = rod.elementLength;
    const auto tip = static_cast<size_t>(rod.numNodes() - 1);
    Eigen::Vector3d m = view.torque[tip];
    double largest = std::max(0.0, relaxJoint(view, tip, m, relaxation, measure));
    if (tip == 0) {
        return largest;
    }
    // Forces at the nodes downstream of i; summed from zero as before, so a
    // -0 in the tip force stays +0 here.
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    f += view.force[tip];
    for (size_t i = tip - 1; i > 0; --i) {
        m += (length * view.frame[i].col(2)).cross(f);  // eq 1: moment about node i (eq 7's lever)
        largest = std::max(largest, relaxJoint(view, i, m, relaxation, measure));
        f += view.force[i];
        m += view.torque[i];  // acts on element i - 1: upstream joints only
    }
    m += (length * view.frame[0].col(2)).cross(f);
    return std::max(largest, relaxJoint(view, 0, m, relaxation, measure));
}

}  // namespace

double solveChain(DiscreteRod& rod, int iterations, double relaxation)
{
    prepareRelaxation(rod, relaxation);
    double largest = 0.0;
    for (int it = 0; it < iterations; ++it) {
        largest = relaxJoints(rod, relaxation, it == iterations - 1);
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
