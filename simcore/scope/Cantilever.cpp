#include "simcore/scope/Cantilever.h"

#include <cmath>

namespace colonosim::scope {

DiscreteRod makeCantilever(int numElements, double length, double flexuralRigidity, double torsionalRigidity,
                           const CantileverLoads& loads)
{
    DiscreteRod rod;
    rod.baseFrame << 0.0, 0.0, 1.0,  //
        0.0, 1.0, 0.0,               //
        -1.0, 0.0, 0.0;
    rod.reset(numElements + 1, length, flexuralRigidity, torsionalRigidity, numElements + 1);
    const Eigen::Vector3d down = -Eigen::Vector3d::UnitY();
    for (int k = 1; k <= numElements; ++k) {
        const double share = k == numElements ? 0.5 : 1.0;
        rod.force[static_cast<size_t>(k)] = share * loads.distributedLoad * rod.elementLength * down;
    }
    rod.force.back() += loads.tipLoad * down;
    rod.torque.back() = Eigen::Vector3d(loads.tipTorque, 0.0, -loads.endMoment);
    return rod;
}

double tipAngle(const DiscreteRod& rod)
{
    const Eigen::Vector3d t = rod.frame.back().col(2);
    return std::atan2(-t.y(), t.x());
}

}  // namespace colonosim::scope
