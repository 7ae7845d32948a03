#pragma once
/// \file
/// Contact of the colon with itself: two parts of the tube that are far apart
/// along the colon may not overlap in space.
///
/// Why. The wall is a mass-spring surface with no contact of its own, so a
/// colon pushed into a fold (the scope driving the sigmoid into a hairpin)
/// let its two limbs pass into each other: in the expert's run on the
/// default colon, rings 14 cm apart along the colon came within 21 mm of
/// each other, centre to centre, with lumen radii of 14 mm. The lumen then
/// overlaps itself, and the scope, which is kept inside the lumen it is in,
/// crossed into the other limb and left the nodes behind its tip 3-9 cm
/// outside the wall.
///
/// Model (only what the scene needs: the lumens, not the folds of the wall).
/// Each ring of wall nodes is a ball of its rest radius r_i about its centre
/// c_i (the mean of its P_i nodes). Two rings i, j whose rest arc lengths
/// differ by more than 2 (r_i + r_j) (a U-bend with its limbs touching spans
/// pi (r_i + r_j) / 2, so nearer rings may overlap in a bend and are never
/// paired) and that overlap by delta = r_i + r_j - |c_i - c_j| > 0 push
/// each other apart with f = k (delta - s / 2) along u = (c_i - c_j) / |c_i - c_j|,
/// its onset smoothed over s = 1 mm (f = k delta^2 / (2 s) below it, so
/// that the Newton solve of the colon's rest state does not cycle on a pair
/// that touches and parts), shared equally by the ring's nodes (f / P_i
/// each; ring j gets the opposite). The force has an energy, so K is symmetric:
///     dF_i/dc_i = -f'(delta) u u^T + (f / d)(I - u u^T),
/// and each node's block is that over P_i P_j. The transverse part is
/// positive; the implicit solve's definite K+ drops it (as for compressed
/// springs). Balls at the ring spacing (14 mm on the default colon, radius
/// 13-22 mm) follow the tube's surface to within about 2 mm.
///
/// A generated colon may already overlap itself at rest where it coils
/// tightly (case seed 7: 42 pairs, up to 36.9 mm; about one case in 20 has
/// such a colon, geometry::lumenSelfOverlap): the rest shape is the
/// stress-free reference, so such a pair keeps its rest overlap as slack
/// and is only kept from overlapping further (delta less the slack).
///
/// Candidate pairs are a Verlet list: the pairs within 10 mm of touching,
/// rebuilt when a ring centre has moved more than 5 mm since the last build,
/// so a force evaluation costs one pass over the ring nodes and the few
/// candidate pairs.

#include "simcore/physics/ForceTerm.h"

#include <vector>

namespace colonosim::physics {

class LumenSelfContact final : public ForceTerm {
public:
    struct Ring {
        std::vector<int> nodes;  ///< the ring's wall nodes (at least 3)
        double arcLength = 0.0;  ///< along the colon at rest, m
        double radius = 0.0;     ///< the lumen's radius at rest, m
    };

    /// `stiffness` k, N/m per metre of overlap (0: no self-contact);
    /// `rest` the nodes' rest positions (m), whose overlaps are slack.
    /// Throws std::invalid_argument for a ring of fewer than 3 nodes or a
    /// non-positive radius.
    LumenSelfContact(std::vector<Ring> rings, double stiffness, const Positions& rest);

    [[nodiscard]] std::string_view name() const override { return "lumen self-contact"; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions&, const Velocities&, Forces&) const override {}
    void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDefiniteStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                     Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const Positions&, const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&) const override {}
    void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const override;
    [[nodiscard]] double potentialEnergy(const Positions& x) const override;
    /// Its pairs come and go with the state: not probed by the static
    /// solver's preconditioner.
    [[nodiscard]] bool couplingsDeclared() const override { return false; }
    /// Rings with an awake node are the ones whose centres move: between two
    /// changes of the awake set, an evaluation at the same positions matrix
    /// recomputes only their centres (a sleeping node does not move, so the
    /// other centres are those of the last full pass, bit for bit).
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override;

    [[nodiscard]] int numRings() const { return static_cast<int>(m_rings.size()); }
    /// Ring pairs that overlap at x beyond their rest overlap, and the
    /// deepest such overlap, m.
    [[nodiscard]] int overlappingPairs(const Positions& x, double* deepest = nullptr) const;

    static constexpr double kListMargin = 10e-3;  ///< m: candidate pairs are within this of touching

private:
    void computeCentres(const Positions& x) const;
    /// Centres at x, and the candidate list rebuilt when a centre moved too far.
    void updateCentres(const Positions& x) const;
    void refreshCandidates() const;
    /// Adds df for the pair's K (definite: without the transverse part).
    void addProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df,
                    bool definite) const;
    [[nodiscard]] Eigen::Vector3d ringMean(int ring, const Eigen::Matrix3Xd& values) const;
    void spread(int ring, const Eigen::Vector3d& total, Eigen::Matrix3Xd& out) const;

    std::vector<Ring> m_rings;
    double m_stiffness;
    struct Pair {
        int i = 0;
        int j = 0;
        double reach = 0.0;  ///< r_i + r_j less the rest overlap, m
    };
    struct Separation {
        Eigen::Vector3d r;   ///< c_i - c_j, m
        double d = 0.0;      ///< |c_i - c_j|, m
        double delta = 0.0;  ///< overlap beyond the rest overlap, m (negative: apart)
    };
    /// The pair at the centres last computed.
    [[nodiscard]] Separation separation(const Pair& pair) const;
    /// visit(pair, c_i - c_j, d, delta) for each candidate pair overlapping at x.
    template <class Visit>
    void forEachOverlap(const Positions& x, Visit&& visit) const;

    std::vector<Pair> m_allowed;  ///< ring pairs far enough apart along the colon
    // Scratch, refreshed on every evaluation (the terms' interface is const).
    mutable std::vector<Eigen::Vector3d> m_centre;
    mutable std::vector<Eigen::Vector3d> m_listCentre;  ///< centres when the list was built
    mutable std::vector<Pair> m_candidates;
    mutable bool m_listBuilt = false;
    std::vector<int> m_movingRings;  ///< rings with at least one awake node (all without a region)
    /// The positions matrix (its data and size) of the last full pass.
    mutable const double* m_centresOf = nullptr;
    mutable Eigen::Index m_centresCols = -1;
};

/// The rings of a procedural colon's physics mesh: runs of consecutive nodes
/// that share one arc length (geometry/ProceduralColon.h), cut into rings of
/// the first ring's size (the cecal dome's two rings share one arc length),
/// each with its rest centre's mean radius. What is left of a run with fewer
/// than 3 nodes (the cecal apex) is left out; a mesh without rings gives none.
[[nodiscard]] std::vector<LumenSelfContact::Ring> lumenRings(const Eigen::Matrix3Xd& restPositions,
                                                             const std::vector<double>& arcLength);

}  // namespace colonosim::physics
