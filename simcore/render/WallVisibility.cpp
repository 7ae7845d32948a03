#include "simcore/render/WallVisibility.h"

#include <algorithm>
#include <cmath>

namespace colonosim::render {

bool wallPointInView(const CameraPose& camera, const Eigen::Vector3d& point, const Eigen::Vector3d& inward,
                     const RenderParameters& parameters)
{
    const Eigen::Vector3d ray = point - camera.position;
    const double distance = ray.norm();
    if (!(distance > 0.0) || distance > parameters.workingDistance) {
        return false;
    }
    const Eigen::Vector3d towards = ray / distance;
    const double offAxis = std::acos(std::clamp(towards.dot(camera.rotation.col(2)), -1.0, 1.0));
    if (offAxis > 0.5 * parameters.fieldOfView) {
        return false;
    }
    // The wall faces the lens: the ray back to the lens against the inward normal.
    return -towards.dot(inward) >= std::cos(parameters.maxIncidence);
}

}  // namespace colonosim::render
