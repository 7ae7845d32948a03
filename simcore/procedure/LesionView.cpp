#include "simcore/procedure/LesionView.h"

#include "simcore/params/Parameter.h"
#include "simcore/render/WallVisibility.h"

#include <cmath>
#include <string>

namespace colonosim::procedure {

LesionView::LesionView(const geometry::ColonAnatomy& anatomy, const std::vector<LesionSite>& sites,
                       const render::RenderParameters& viewing)
    : m_anatomy(anatomy), m_viewing(viewing)
{
    if (sites.size() > static_cast<size_t>(kMaxLesions)) {
        throw params::ParameterError("lesions: " + std::to_string(sites.size()) +
                                     " lesions is outside the allowed range [0, " +
                                     std::to_string(kMaxLesions) + "]");
    }
    const geometry::TriangleMesh& mesh = anatomy.physicsMesh;
    for (size_t k = 0; k < sites.size(); ++k) {
        const int nearest = wallNodeAt(anatomy, sites[k], "lesions[" + std::to_string(k) + "]");
        m_node.push_back(nearest);
        std::vector<int> around;
        for (int t = 0; t < mesh.numTriangles(); ++t) {
            const auto& tri = mesh.triangles[static_cast<size_t>(t)];
            if (tri[0] == nearest || tri[1] == nearest || tri[2] == nearest) {
                around.push_back(t);
            }
        }
        m_triangles.push_back(std::move(around));
    }
}

std::uint32_t LesionView::inView(const Eigen::Matrix3Xd& positions, const scope::TipPose& tip) const
{
    const render::CameraPose camera{tip.position, tip.rotation};
    std::uint32_t bits = 0;
    for (size_t k = 0; k < m_node.size(); ++k) {
        Eigen::Vector3d outward = Eigen::Vector3d::Zero();
        for (const int t : m_triangles[k]) {
            const auto& tri = m_anatomy.physicsMesh.triangles[static_cast<size_t>(t)];
            const Eigen::Vector3d a = positions.col(tri[0]);
            outward += (positions.col(tri[1]) - a).cross(positions.col(tri[2]) - a);  // out of the lumen
        }
        const double norm = outward.norm();
        if (norm > 0.0 &&
            render::wallPointInView(camera, positions.col(m_node[k]), -outward / norm, m_viewing)) {
            bits |= std::uint32_t{1} << k;
        }
    }
    return bits;
}

}  // namespace colonosim::procedure
