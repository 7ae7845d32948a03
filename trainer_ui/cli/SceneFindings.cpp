#include "trainer_ui/cli/SceneFindings.h"

#include "simcore/physics/Gravity.h"

#include <utility>

namespace colonosim::cli {

render::WallFindings findingsOf(const cases::SceneSpec& scene)
{
    render::WallFindings findings;
    for (const cases::SceneLesion& lesion : scene.lesions) {
        render::Lesion out;
        out.place = {lesion.place.arcLength, lesion.place.angle};
        out.diameter = lesion.diameter;
        switch (lesion.paris) {
        case cases::Paris::Ip: out.shape = render::LesionShape::Pedunculated; break;
        case cases::Paris::IIa:
        case cases::Paris::IIb:
        case cases::Paris::LstGranular:
        case cases::Paris::LstNonGranular: out.shape = render::LesionShape::Flat; break;
        case cases::Paris::IIc: out.shape = render::LesionShape::Depressed; break;
        default: out.shape = render::LesionShape::Sessile;
        }
        switch (lesion.histology) {
        case cases::Histology::Hyperplastic:
        case cases::Histology::SessileSerrated:
        case cases::Histology::TraditionalSerrated: out.tissue = render::LesionTissue::Serrated; break;
        case cases::Histology::Lipoma: out.tissue = render::LesionTissue::Lipoma; break;
        case cases::Histology::Adenocarcinoma: out.tissue = render::LesionTissue::Cancer; break;
        default: out.tissue = render::LesionTissue::Adenoma;
        }
        findings.lesions.push_back(out);
    }
    for (const cases::SceneDiverticulum& pocket : scene.diverticula) {
        findings.diverticula.push_back({{pocket.place.arcLength, pocket.place.angle}, pocket.diameter});
    }
    for (int s = 0; s < geometry::kNumSegments; ++s) {
        const auto region = cases::bowelRegion(static_cast<geometry::Segment>(s));
        findings.stoolFraction[static_cast<size_t>(s)] = scene.residualStool[static_cast<size_t>(region)];
    }
    // Each region's fluid flows within the region's segments to its level.
    for (int r = 0; r < cases::kNumBowelRegions; ++r) {
        render::FluidPool pool;
        pool.volume = scene.residualFluid[static_cast<size_t>(r)];
        for (int s = 0; s < geometry::kNumSegments; ++s) {
            if (cases::bowelRegion(static_cast<geometry::Segment>(s)) == static_cast<cases::BowelRegion>(r)) {
                pool.segments.push_back(static_cast<geometry::Segment>(s));
            }
        }
        if (pool.volume > 0.0) {
            findings.fluid.push_back(std::move(pool));
        }
    }
    findings.down = physics::downDirection(scene.environment.patientPosition);
    return findings;
}

}  // namespace colonosim::cli
