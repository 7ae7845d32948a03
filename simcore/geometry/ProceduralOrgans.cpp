#include "simcore/geometry/ProceduralOrgans.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

namespace colonosim::geometry {

namespace {

double minSignedDistance(const ImplicitShape& shape, const TriangleMesh& mesh)
{
    double minimum = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i) {
        minimum = std::min(minimum, shape.signedDistance(mesh.vertices.col(i), nullptr));
    }
    return minimum;
}

void translate(ImplicitShape& shape, const Eigen::Vector3d& delta)
{
    shape.centre += delta;
    shape.capsuleA += delta;
    shape.capsuleB += delta;
}

/// Slides `shape` along `direction` until every rest node clears it.
void clearRestNodes(ImplicitShape& shape, const TriangleMesh& mesh, const Eigen::Vector3d& direction)
{
    for (int it = 0; it < 200; ++it) {
        const double clearance = minSignedDistance(shape, mesh);
        if (clearance >= kOrganClearance) {
            return;
        }
        translate(shape, (kOrganClearance - clearance + 0.002) * direction.normalized());
    }
}

ImplicitShape ellipsoid(std::string name, const Eigen::Vector3d& centre, const Eigen::Vector3d& semiAxes)
{
    ImplicitShape shape;
    shape.name = std::move(name);
    shape.kind = ImplicitShape::Kind::Ellipsoid;
    shape.centre = centre;
    shape.semiAxes = semiAxes;
    return shape;
}

}  // namespace

std::vector<ImplicitShape> placeProceduralOrgans(const ColonLayout& layout, const TriangleMesh& restMesh)
{
    const double k = layout.bodyScale;
    const auto& st = layout.stations;
    const Eigen::Vector3d hepatic = st[static_cast<std::size_t>(Segment::HepaticFlexure)];
    const Eigen::Vector3d splenic = st[static_cast<std::size_t>(Segment::SplenicFlexure)];
    const Eigen::Vector3d descendingTop = st[static_cast<std::size_t>(Segment::SplenicFlexure)];
    const Eigen::Vector3d ascendingTop = st[static_cast<std::size_t>(Segment::Ascending)];

    std::vector<ImplicitShape> organs;
    organs.push_back(ellipsoid("liver", hepatic + k * Eigen::Vector3d(-0.01, 0.02, 0.10),
                               k * Eigen::Vector3d(0.10, 0.075, 0.06)));
    organs.push_back(ellipsoid("spleen", splenic + k * Eigen::Vector3d(0.04, 0.06, 0.06),
                               k * Eigen::Vector3d(0.035, 0.06, 0.06)));
    organs.push_back(ellipsoid("left_kidney", descendingTop + k * Eigen::Vector3d(-0.06, 0.07, -0.07),
                               k * Eigen::Vector3d(0.03, 0.025, 0.055)));
    organs.push_back(ellipsoid("right_kidney", ascendingTop + k * Eigen::Vector3d(0.06, 0.06, -0.03),
                               k * Eigen::Vector3d(0.03, 0.025, 0.055)));
    organs.push_back(
        ellipsoid("bladder", k * Eigen::Vector3d(0.0, -0.05, 0.07), k * Eigen::Vector3d(0.045, 0.035, 0.04)));
    ImplicitShape spine;
    spine.name = "spine";
    spine.kind = ImplicitShape::Kind::Capsule;
    spine.capsuleA = k * Eigen::Vector3d(0.0, 0.13, 0.08);
    spine.capsuleB = k * Eigen::Vector3d(0.0, 0.15, 0.50);
    spine.capsuleRadius = k * 0.025;
    organs.push_back(spine);

    const std::array<Eigen::Vector3d, 6> away{{Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ(),
                                               Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY(),
                                               -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY()}};
    for (std::size_t i = 0; i < organs.size(); ++i) {
        clearRestNodes(organs[i], restMesh, away[i]);
    }

    // Abdominal cavity: an axis-aligned ellipsoid around the rest nodes,
    // grown until every node is inside by kCavityMargin.
    const Eigen::Vector3d lo = restMesh.vertices.rowwise().minCoeff();
    const Eigen::Vector3d hi = restMesh.vertices.rowwise().maxCoeff();
    ImplicitShape cavity = ellipsoid("abdominal_cavity", 0.5 * (lo + hi),
                                     0.5 * (hi - lo) + Eigen::Vector3d::Constant(kCavityMargin));
    cavity.side = ImplicitShape::Side::KeepInside;
    for (int it = 0; it < 200; ++it) {
        double worst = -std::numeric_limits<double>::infinity();
        for (Eigen::Index i = 0; i < restMesh.vertices.cols(); ++i) {
            worst = std::max(worst, cavity.signedDistance(restMesh.vertices.col(i), nullptr));
        }
        if (worst <= -kCavityMargin) {
            break;
        }
        cavity.semiAxes *= 1.02;
    }
    organs.push_back(cavity);
    return organs;
}

}  // namespace colonosim::geometry
