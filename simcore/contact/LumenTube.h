#pragma once
/// \file
/// The colon's lumen as a chain of rings of wall nodes, for contact that
/// always knows which way is in.
///
/// The procedural physics mesh (geometry/ProceduralColon.h) is a tube of
/// rings: ring i holds nodes i P .. i P + P - 1 (P nodes per ring, node j at
/// angle 2 pi j / P), the last ring is the cecal dome ring, and one apex node
/// closes the tube. Each step, from the current wall positions, every ring
/// gets its centre c_i (mean of its nodes), its axis a_i (the unit direction
/// c_{i+1} - c_{i-1}, one-sided at the ends) and the 2-D coordinates of its
/// nodes in its own plane (basis: node 0's radial direction, and a_i x it).
///
/// Station of a point p: a nearest point of the polyline of ring centres,
/// section (i, i + 1) at fraction u in [0, 1], found by walking along the
/// polyline from a nearby section (LumenContact.h says which) while the
/// distance falls, a few sections at most; never globally: a point pushed
/// outside the wall stays in its own part of the colon and is pushed back
/// the way it came, so the lumen cannot be tunnelled into a neighbouring
/// loop at any speed. A walk, not the nearest section within reach: where
/// the colon folds on itself (a flattened ring at a hairpin) the other leg
/// of the fold can lie nearer across the wall. (The nearest point and not
/// the bracketing ring planes, which cross on the inner side of a bend.)
/// A walk can also be held at a fold with the point outside its section's
/// wall while it lies inside another's a few sections on: findHolding()
/// finds that section, and LumenContact.h says when it is taken.
///
/// Wall at a station along a radial direction e (perpendicular to the local
/// axis): the ray from each ring's centre along e meets the ring polygon at
/// radius R_i on edge (j, j + 1) at fraction w; the wall radius is
/// R = (1 - u) R_i + u R_{i+1}, and the wall point's nodes and weights are
/// the bilinear ones: (1 - u)(1 - w_i), (1 - u) w_i, u (1 - w_{i+1}), u w_{i+1}.
/// Beyond the dome ring the tube is closed by the apex.

#include "simcore/geometry/ColonAnatomy.h"

#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace colonosim::contact {

/// Where a point lies along the lumen: section (ring, ring + 1) at fraction u.
struct LumenStation {
    int ring = 0;
    double u = 0.0;
    bool beyondEnd = false;    ///< past the dome ring's plane (the closed cecal end)
    bool beforeStart = false;  ///< before the first ring's plane (outside the anus)
};

/// The wall of the lumen seen from a point at a station.
struct LumenWallSample {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< lumen centre at the station, m
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< unit lumen axis at the station
    Eigen::Vector3d radial = Eigen::Vector3d::Zero();  ///< unit direction from the centre to the point
    double distance = 0.0;                             ///< point's distance from the axis, m
    double wallRadius = 0.0;                           ///< wall's distance from the axis along `radial`, m
    std::array<int, 4> nodes{};                        ///< wall nodes of the wall point
    std::array<double, 4> weights{};                   ///< their bilinear weights (sum 1)
};

class LumenTube {
public:
    /// Reads the ring structure of `anatomy`'s physics mesh; throws
    /// params::ParameterError naming what does not fit (a mesh that is not a
    /// tube of rings, e.g. an imported one).
    explicit LumenTube(const geometry::ColonAnatomy& anatomy);

    [[nodiscard]] int numRings() const { return m_numRings; }
    [[nodiscard]] int nodesPerRing() const { return m_perRing; }
    [[nodiscard]] int apex() const { return m_apex; }
    [[nodiscard]] int node(int ring, int j) const { return ring * m_perRing + (j % m_perRing); }

    /// Recomputes centres, axes and in-plane coordinates from `wall` (3 x nodes, m).
    void update(const Eigen::Matrix3Xd& wall);

    [[nodiscard]] const Eigen::Vector3d& centre(int ring) const
    {
        return m_centre[static_cast<size_t>(ring)];
    }
    [[nodiscard]] const Eigen::Vector3d& axis(int ring) const { return m_axis[static_cast<size_t>(ring)]; }
    /// Signed distance of `p` ahead of ring `ring`'s plane, m.
    [[nodiscard]] double height(int ring, const Eigen::Vector3d& p) const
    {
        return (p - centre(ring)).dot(axis(ring));
    }
    /// The section holding `p`: the nearest point of the centre polyline
    /// reached by walking from section `start` while the distance falls, at
    /// most `window` sections.
    [[nodiscard]] LumenStation locate(const Eigen::Vector3d& p, int start, int window = 4) const;
    /// Whether the wall of section `ring` holds `p`: p lies between the
    /// section's two rings (its nearest point on the section is not an end)
    /// and nearer the axis than the wall. `at` receives the station.
    [[nodiscard]] bool holds(const Eigen::Vector3d& p, int ring, LumenStation& at) const;
    /// The section nearest to `from` (at most `window` sections away) whose
    /// wall holds `p` and that lies nearer to section `towards` than `from`
    /// does; false if there is none. For a point whose walk was held at a
    /// fold (see LumenContact.h).
    ///
    /// With `neighbour` (the base-side point, at section `towards`), a
    /// section away from `towards` is also taken when the segment from the
    /// neighbour to `p` passes through every ring between the two sections
    /// within `slack` of its wall (passesThrough()): the colon pleated on the
    /// shaft, its rings packed closer than the points and tilted so that the
    /// walk is held on a fold of the pleat, not a point pushed through the
    /// wall into a neighbouring loop (the segment would leave the lumen).
    [[nodiscard]] bool findHolding(const Eigen::Vector3d& p, int from, int towards, int window,
                                   LumenStation& at, const Eigen::Vector3d* neighbour = nullptr,
                                   double slack = 0.0) const;
    /// Whether the segment from `q` to `p` crosses the plane of every ring
    /// between sections `from` and `to` (rings from + 1 .. to, or to + 1 ..
    /// from) no further from its centre than its wall along the same
    /// direction plus `slack`, m: a path inside the lumen from one section
    /// to the other.
    [[nodiscard]] bool passesThrough(const Eigen::Vector3d& q, const Eigen::Vector3d& p, int from, int to,
                                     double slack) const;
    /// The wall seen from `p` at `station`, radially.
    [[nodiscard]] LumenWallSample wallAt(const Eigen::Vector3d& p, const LumenStation& station) const;
    /// Where a station lies along the colon at rest (material coordinate), m:
    /// the rings' arc lengths interpolated; the tube's ends clamp.
    [[nodiscard]] double arcLength(const LumenStation& at) const;
    /// How far the closed end lies ahead of the dome ring's plane, m (apex height).
    [[nodiscard]] double endHeight() const { return m_endHeight; }
    /// The lumen centre `distance` metres along the axis from station `from`
    /// (negative: back towards the anus), following the ring centres.
    [[nodiscard]] Eigen::Vector3d centreAlong(const LumenStation& from, double distance) const;

private:
    /// Fraction along section (ring, ring + 1) of `p`'s projection onto its
    /// centre line, unclamped (-1 for a section of zero length: it holds
    /// nothing, and its nearest point is its first ring's centre).
    [[nodiscard]] double sectionFraction(const Eigen::Vector3d& p, int ring) const;
    /// Ray from ring `ring`'s centre along the 3-D direction `e`: radius, edge and fraction.
    void rayToRing(int ring, const Eigen::Vector3d& e, double& radius, int& edge, double& fraction) const;

    int m_numRings = 0;
    int m_perRing = 0;
    int m_apex = -1;
    double m_endHeight = 0.0;
    std::vector<double> m_ringArc;  ///< each ring's arc length along the colon at rest, m
    std::vector<Eigen::Vector3d> m_centre, m_axis, m_basisU, m_basisV;
    std::vector<Eigen::Vector2d> m_planar;  ///< per node of the rings, in its ring's plane, m
};

}  // namespace colonosim::contact
