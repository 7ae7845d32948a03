#pragma once
/// \file
/// The camera at the scope tip and the CPU twin of the shaders' equidistant
/// fisheye (Shaders.h): an image-circle radius proportional to the angle
/// from the view axis, r = theta / (fieldOfView / 2), the circle filling the
/// image height.
///
/// Camera frame: the tip pose's rotation (columns x, up, forward, a
/// rotation with det +1, as scope::TipPose). For a viewer looking along
/// forward with up at the top, forward x up points to the image's right;
/// with a det +1 frame that is minus the x column, so the image is
/// drawn as a real lens sees it (not mirrored).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>

namespace colonosim::render {

struct CameraPose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m, world
    Eigen::Matrix3d rotation =
        Eigen::Matrix3d::Identity();  ///< as scope::TipPose: x the viewer's left, y up, z forward
};

/// World-to-camera rotation whose rows are the image x axis (forward x up),
/// the image y axis (up) and the view axis (forward).
[[nodiscard]] Eigen::Matrix3d worldToCamera(const CameraPose& pose);

struct FisheyeLens {
    double fieldOfView = 2.7925;  ///< rad, full angle of the image circle
    int width = 640;              ///< pixels
    int height = 480;             ///< pixels

    /// Pixel coordinates (x right, y down, pixel centres at +0.5) of a world
    /// point, or nothing when it lies outside the image circle.
    [[nodiscard]] std::optional<Eigen::Vector2d> project(const CameraPose& pose,
                                                         const Eigen::Vector3d& point) const;
};

}  // namespace colonosim::render
