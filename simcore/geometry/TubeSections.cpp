#include "simcore/geometry/TubeSections.h"

#include <algorithm>
#include <cmath>

namespace colonosim::geometry::surface {

/// Iso-contours of the piecewise-linear `field` at levels first + k step,
/// k = 0..count-1 (marching triangles). Each triangle visits only the levels
/// inside its value range, so the cost is O(F + number of contour segments).
std::vector<Section> levelSets(const TriangleMesh& mesh, const std::vector<double>& field, double first,
                               double step, int count)
{
    struct Piece {
        int level;
        Eigen::Vector3d p, q;
    };
    std::vector<Piece> pieces;
    std::vector<Section> sections(static_cast<std::size_t>(count));
    for (const auto& t : mesh.triangles) {
        const double f[3] = {field[static_cast<std::size_t>(t[0])], field[static_cast<std::size_t>(t[1])],
                             field[static_cast<std::size_t>(t[2])]};
        if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2]))
            continue;
        const double lo = std::min({f[0], f[1], f[2]});
        const double hi = std::max({f[0], f[1], f[2]});
        // Levels l with lo < l <= hi: vertices with f >= l are "above".
        int k0 = std::max(0, static_cast<int>(std::ceil((lo - first) / step)));
        if (first + k0 * step <= lo)
            ++k0;
        const int k1 = std::min(count - 1, static_cast<int>(std::floor((hi - first) / step)));
        for (int k = k0; k <= k1; ++k) {
            const double level = first + k * step;
            Eigen::Vector3d ends[2];
            int n = 0;
            for (std::size_t e = 0; e < 3 && n < 2; ++e) {
                const std::size_t e1 = (e + 1) % 3;
                if ((f[e] >= level) != (f[e1] >= level)) {
                    const double u = (level - f[e]) / (f[e1] - f[e]);
                    ends[n++] = (1.0 - u) * mesh.vertices.col(t[e]) + u * mesh.vertices.col(t[e1]);
                }
            }
            if (n < 2)
                continue;
            const double len = (ends[1] - ends[0]).norm();
            Section& s = sections[static_cast<std::size_t>(k)];
            s.centre += 0.5 * len * (ends[0] + ends[1]);
            s.contourLength += len;
            pieces.push_back({k, ends[0], ends[1]});
        }
    }
    for (Section& s : sections) {
        if (s.contourLength > 0.0)
            s.centre /= s.contourLength;
    }
    for (const Piece& piece : pieces) {
        Section& s = sections[static_cast<std::size_t>(piece.level)];
        const double len = (piece.q - piece.p).norm();
        s.radius += 0.5 * len * ((piece.p - s.centre).norm() + (piece.q - s.centre).norm());
    }
    for (Section& s : sections) {
        if (s.contourLength > 0.0)
            s.radius /= s.contourLength;
    }
    return sections;
}

}  // namespace colonosim::geometry::surface
