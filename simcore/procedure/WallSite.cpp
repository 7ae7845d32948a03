#include "simcore/procedure/WallSite.h"

#include "simcore/geometry/CentrelineSampling.h"
#include "simcore/params/Parameter.h"

#include <cmath>

namespace colonosim::procedure {

int wallNodeAt(const geometry::ColonAnatomy& anatomy, const WallSite& site, const std::string& field)
{
    const double length = anatomy.centreline.length();
    if (!(site.arcLength >= 0.0 && site.arcLength <= length)) {
        throw params::ParameterError(field + ".arcLength = " + std::to_string(site.arcLength) +
                                     " m is outside the allowed range [0, " + std::to_string(length) +
                                     "] m (the colon's length)");
    }
    if (!std::isfinite(site.angle)) {
        throw params::ParameterError(field + ".angle = " + std::to_string(site.angle) +
                                     " rad is not a finite angle");
    }
    const geometry::CentrelineSample at = geometry::sampleCentreline(anatomy.centreline, site.arcLength);
    const Eigen::Vector3d place =
        at.point + at.radius * (std::cos(site.angle) * at.normal + std::sin(site.angle) * at.binormal);
    int nearest = 0;
    (anatomy.physicsMesh.vertices.colwise() - place).colwise().squaredNorm().minCoeff(&nearest);
    return nearest;
}

}  // namespace colonosim::procedure
