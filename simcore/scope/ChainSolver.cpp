#include "simcore/scope/ChainSolver.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace colonosim::scope {

double solveChain(DiscreteRod& rod, int iterations, double relaxation)
{
    const int n = rod.numNodes();
    double largest = 0.0;
    for (int it = 0; it < iterations; ++it) {
        largest = 0.0;
        Eigen::Vector3d f = Eigen::Vector3d::Zero();  // forces at the nodes downstream of k
        Eigen::Vector3d m = rod.torque[static_cast<size_t>(n - 1)];
        for (int k = n - 1; k >= 0; --k) {
            const auto i = static_cast<size_t>(k);
            if (k < n - 1) {
                m += (rod.position[i + 1] - rod.position[i]).cross(f);  // eq 1: moment about node k
            }
            const Eigen::Vector3d stiffness = rod.jointStiffness(k);
            const Eigen::Vector3d& damping = rod.damping[i];
            const Eigen::Vector3d net = rod.frame[i].transpose() * m - stiffness.cwiseProduct(rod.theta[i]) -
                                        damping.cwiseProduct(rod.theta[i] - rod.thetaStart[i]);
            const Eigen::Vector3d step = relaxation * net.cwiseQuotient(stiffness + damping);
            rod.theta[i] += step;  // eqs 4-5
            largest = std::max(largest, step.cwiseAbs().maxCoeff());
            f += rod.force[i];
            if (k > 0 && k < n - 1) {
                m += rod.torque[i];  // acts on element k - 1: upstream joints only
            }
        }
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
