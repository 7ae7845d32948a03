#include "simcore/render/FisheyeLens.h"

#include <algorithm>
#include <cmath>

namespace colonosim::render {

Eigen::Matrix3d worldToCamera(const CameraPose& pose)
{
    const Eigen::Vector3d up = pose.rotation.col(1);
    const Eigen::Vector3d forward = pose.rotation.col(2);
    Eigen::Matrix3d m;
    m.row(0) = forward.cross(up).transpose();
    m.row(1) = up.transpose();
    m.row(2) = forward.transpose();
    return m;
}

std::optional<Eigen::Vector2d> FisheyeLens::project(const CameraPose& pose,
                                                    const Eigen::Vector3d& point) const
{
    const Eigen::Vector3d c = worldToCamera(pose) * (point - pose.position);
    const double d = c.norm();
    if (d <= 0.0) {
        return std::nullopt;
    }
    const double theta = std::acos(std::clamp(c.z() / d, -1.0, 1.0));
    const double half = fieldOfView / 2.0;
    if (theta > half) {
        return std::nullopt;
    }
    const double rxy = std::hypot(c.x(), c.y());
    const Eigen::Vector2d direction =
        rxy > 1e-12 ? Eigen::Vector2d(c.x() / rxy, c.y() / rxy) : Eigen::Vector2d::Zero();
    const Eigen::Vector2d ndc = direction * (theta / half);
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    return Eigen::Vector2d((ndc.x() / aspect + 1.0) / 2.0 * width, (1.0 - ndc.y()) / 2.0 * height);
}

}  // namespace colonosim::render
