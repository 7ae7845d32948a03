#pragma once
// Simple scenes with known answers for the renderer's tests: a straight tube
// along +z and its centreline.

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/TriangleMesh.h"
#include "simcore/render/FisheyeLens.h"
#include "simcore/render/Image.h"

#include <QImage>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace colonosim::testing {

/// Open tube of radius r (m) from z = 0 to z = length, rings every `spacing`
/// m, `around` vertices per ring; normals point out of the lumen.
inline geometry::TriangleMesh straightTube(double radius, double length, double spacing, int around)
{
    const int rings = static_cast<int>(std::lround(length / spacing)) + 1;
    geometry::TriangleMesh mesh;
    mesh.vertices.resize(3, rings * around);
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < around; ++j) {
            const double a = 2.0 * std::numbers::pi * j / around;
            mesh.vertices.col(i * around + j) =
                Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), length * i / (rings - 1));
        }
    }
    for (int i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j < around; ++j) {
            const int a = i * around + j;
            const int b = i * around + (j + 1) % around;
            const int c = a + around;
            const int d = b + around;
            mesh.triangles.push_back({a, b, d});
            mesh.triangles.push_back({a, d, c});
        }
    }
    return mesh;
}

inline geometry::Centreline straightCentreline(double radius, double length, double spacing)
{
    geometry::Centreline c;
    const int n = static_cast<int>(std::lround(length / spacing)) + 1;
    for (int i = 0; i < n; ++i) {
        const double z = length * i / (n - 1);
        c.points.emplace_back(0.0, 0.0, z);
        c.arcLength.push_back(z);
        c.tangents.emplace_back(0.0, 0.0, 1.0);
        c.normals.emplace_back(1.0, 0.0, 0.0);
        c.radius.push_back(radius);
        c.segment.push_back(geometry::Segment::Descending);
    }
    return c;
}

/// Looking down the tube from `z` on its axis: forward +z, up +y.
inline render::CameraPose axialPose(double z)
{
    render::CameraPose pose;
    pose.position = Eigen::Vector3d(0.0, 0.0, z);
    pose.rotation = Eigen::Matrix3d::Identity();
    return pose;
}

/// Looking straight at the wall of a tube of radius `radius` (forward +x)
/// from `distance` inside it (negative: beyond the wall), 15 cm along the
/// tube, up along the tube.
inline render::CameraPose facingWall(double radius, double distance)
{
    render::CameraPose pose;
    pose.position = Eigen::Vector3d(radius - distance, 0.0, 0.15);
    pose.rotation.col(2) = Eigen::Vector3d::UnitX();
    pose.rotation.col(1) = Eigen::Vector3d::UnitZ();
    pose.rotation.col(0) = pose.rotation.col(1).cross(pose.rotation.col(2));
    return pose;
}

inline double luminance(const render::RgbaImage& image, int x, int y)
{
    const auto* p = image.at(x, y);
    return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

/// Writes a PNG into the test artefacts folder for a person to look at.
inline void saveArtefact(const render::RgbaImage& image, const std::string& name)
{
    const std::filesystem::path dir(COLONOSIM_TEST_ARTEFACTS);
    std::filesystem::create_directories(dir);
    QImage q(image.pixels.data(), image.width, image.height, image.width * 4, QImage::Format_RGBA8888);
    q.save(QString::fromStdString((dir / name).string()));
}

}  // namespace colonosim::testing
