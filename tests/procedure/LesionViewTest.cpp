/// \file
/// The "lesion in view" signal: a lesion on the wall of the default colon is
/// in view from a camera looking at it from inside the lumen within the
/// working distance, and not when the camera looks away, stands too far, or
/// sees the wall edge-on; bad lesion places are refused by name.

#include "simcore/procedure/LesionView.h"
#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/params/Parameter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace colonosim::procedure {
namespace {

const geometry::ColonAnatomy& colon()
{
    static const geometry::ColonAnatomy anatomy =
        geometry::buildProceduralColon(geometry::AnatomyParameters{});
    return anatomy;
}

/// A camera at `distance` from the lesion's node along the lumen's inward
/// direction, looking along `forward` (the node is at -distance * inward from it).
scope::TipPose cameraAt(const Eigen::Vector3d& node, const Eigen::Vector3d& inward, double distance,
                        const Eigen::Vector3d& forward)
{
    scope::TipPose pose;
    pose.position = node + distance * inward;
    const Eigen::Vector3d z = forward.normalized();
    const Eigen::Vector3d helper =
        std::abs(z.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d y = z.cross(helper).normalized().cross(z);  // up, normal to forward
    pose.rotation.col(0) = y.cross(z);                                // x = up x forward
    pose.rotation.col(1) = y;
    pose.rotation.col(2) = z;
    return pose;
}

TEST(LesionView, SeenFacingWithinReachAndNotOtherwise)
{
    const geometry::ColonAnatomy& anatomy = colon();
    const LesionView view(anatomy, {LesionSite{0.3, 0.0}, LesionSite{0.9, 2.0}}, render::RenderParameters{});
    ASSERT_EQ(view.count(), 2);
    const Eigen::Matrix3Xd& wall = anatomy.physicsMesh.vertices;
    const Eigen::Vector3d node = wall.col(view.node(0));
    const geometry::CentrelineSample at = geometry::sampleCentreline(anatomy.centreline, 0.3);
    const Eigen::Vector3d inward = (at.point - node).normalized();
    // The lesion's node lies where the case puts it: angle 0 is the frame's normal.
    EXPECT_GT((node - at.point).normalized().dot(at.normal), 0.95);

    EXPECT_EQ(view.inView(wall, cameraAt(node, inward, 0.02, -inward)), 0b01U);  // looking at it
    EXPECT_EQ(view.inView(wall, cameraAt(node, inward, 0.02, inward)), 0U);      // looking away
    EXPECT_EQ(view.inView(wall, cameraAt(node, inward, 0.06, -inward)), 0U);     // beyond 5 cm
    // Along the lumen, 2 cm off the wall and 3 cm back: seen obliquely (about 56 degrees).
    const Eigen::Vector3d back = node + 0.015 * inward - 0.03 * at.tangent;
    scope::TipPose oblique = cameraAt(back, Eigen::Vector3d::Zero(), 0.0, node - back);
    EXPECT_EQ(view.inView(wall, oblique), 0b01U);
    // Grazing: the camera in the wall's plane looks along it (incidence ~90 degrees).
    const Eigen::Vector3d grazing = node - 0.03 * at.tangent;
    EXPECT_EQ(view.inView(wall, cameraAt(grazing, Eigen::Vector3d::Zero(), 0.0, node - grazing)), 0U);
}

TEST(LesionView, BadPlacesAreRefusedByName)
{
    const geometry::ColonAnatomy& anatomy = colon();
    try {
        const LesionView view(anatomy, {LesionSite{0.3, 0.0}, LesionSite{5.0, 0.0}},
                              render::RenderParameters{});
        FAIL() << "a lesion beyond the colon was accepted";
    } catch (const params::ParameterError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("lesions[1].arcLength = 5"), std::string::npos) << what;
        EXPECT_NE(what.find("allowed range [0, "), std::string::npos) << what;
    }
    EXPECT_THROW(LesionView(anatomy, {LesionSite{0.3, std::nan("")}}, render::RenderParameters{}),
                 params::ParameterError);
    EXPECT_THROW(
        LesionView(anatomy, std::vector<LesionSite>(33, LesionSite{0.3, 0.0}), render::RenderParameters{}),
        params::ParameterError);
}

}  // namespace
}  // namespace colonosim::procedure
