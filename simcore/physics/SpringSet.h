#pragma once
/// \file
/// Linear springs with viscous damping between node pairs, in flat arrays.
///
/// For a spring (i, j) with d = x_j - x_i, l = |d|, u = d / l, rest length L,
/// stiffness k (N/m), damping c (N s/m) and transverse damping ratio t:
///   f_i = k (l - L) u + D_e (v_j - v_i),  f_j = -f_i,
///   D_e = c [(1 - t) u u^T + t I].
/// t = 0 damps only the rate of stretch; t = 1 damps every relative motion
/// of the two ends, the viscosity of a tissue (a membrane of springs damped
/// only along them keeps its out-of-plane modes undamped: ColonBody.h).
/// Stiffness block (df_i/dx_j): K_e = k [(1 - L/l)(I - u u^T) + u u^T], with
/// df_i/dx_i = -K_e; the damping block D_e likewise.
/// Structural, shear and bending springs (the NASA paper's "torsion between
/// adjacent triangles") are all of this kind; `family` tags each for calibration.
/// Springs shorter than kMinLength (1e-12 m) have no direction and exert no force.

#include "simcore/physics/ForceTerm.h"
#include "simcore/physics/SpringKernel.h"

#include <string>

namespace colonosim::physics {

enum class SpringFamily : std::uint8_t { Structural, Shear, Bending, Lesion };

class SpringSet final : public ForceTerm {
public:
    static constexpr double kMinLength = kMinSpringLength;  ///< m

    explicit SpringSet(std::string name = "springs") : m_name(std::move(name)) {}

    /// Adds a spring; returns its index. k in N/m, c in N s/m, L in m.
    int add(int i, int j, double restLength, double stiffness, double damping,
            SpringFamily family = SpringFamily::Structural);
    /// Removes spring `s` by moving the last spring into its slot (O(1)).
    void remove(int s);

    [[nodiscard]] int numSprings() const { return static_cast<int>(m_i.size()); }
    [[nodiscard]] int nodeA(int s) const { return m_i[static_cast<size_t>(s)]; }
    [[nodiscard]] int nodeB(int s) const { return m_j[static_cast<size_t>(s)]; }
    [[nodiscard]] double restLength(int s) const { return m_rest[static_cast<size_t>(s)]; }
    [[nodiscard]] double stiffness(int s) const { return m_k[static_cast<size_t>(s)]; }
    [[nodiscard]] double damping(int s) const { return m_c[static_cast<size_t>(s)]; }
    [[nodiscard]] SpringFamily family(int s) const { return m_family[static_cast<size_t>(s)]; }
    void setStiffness(int s, double stiffness, double damping);
    /// Fraction t of each spring's damping c that acts on the whole relative
    /// velocity of its ends, c [(1 - t) u u^T + t I] dv, rather than along the
    /// spring alone (t = 0). Throws std::invalid_argument outside [0, 1].
    void setTransverseDamping(double ratio);
    [[nodiscard]] double transverseDamping() const { return m_transverseDamping; }
    /// Largest tensile strain (l - L) / L of the springs of `family` at x (1; 0 if none is stretched).
    [[nodiscard]] double maxTensileStrain(const Positions& x, SpringFamily family) const;

    [[nodiscard]] std::string_view name() const override { return m_name; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions& x, const Velocities& v, Forces& f) const override;
    void addForceAndDamping(const Positions& x, const Velocities& v, Forces& f) const override;
    void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDefiniteStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                     Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv,
                           Eigen::Matrix3Xd& df) const override;
    bool linearize(const Positions& x, double h) override;
    void addSystemProduct(const Eigen::Matrix3Xd& y, Eigen::Matrix3Xd& out) const override;
    void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const override;
    void addCouplings(std::vector<std::pair<int, int>>& pairs) const override;
    [[nodiscard]] double potentialEnergy(const Positions& x) const override;
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override;

private:
    template <bool Definite>
    void stiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx, Eigen::Matrix3Xd& df) const;

    [[nodiscard]] Eigen::Vector3d dampingForce(double c, const Eigen::Vector3d& d, double l2,
                                               const Eigen::Vector3d& relativeVelocity) const;

    std::string m_name;
    double m_transverseDamping = 0.0;
    std::vector<int> m_i;
    std::vector<int> m_j;
    std::vector<double> m_rest;
    std::vector<double> m_k;
    std::vector<double> m_c;
    std::vector<SpringFamily> m_family;
    std::vector<int> m_active;  ///< springs with at least one awake node
    std::vector<std::uint8_t> m_awake;
    /// The active springs as addForceAndDamping() reads them
    /// (SpringKernel.h), in m_active's order. Kept in step by every change of
    /// the springs, their stiffness, the transverse damping or the active set.
    std::vector<PackedSpring> m_packed;
    std::vector<int> m_packedSlot;  ///< per spring: its index in m_packed, -1 when inactive
    /// Each node's packed springs and the kernel's scratch (SpringKernel.h),
    /// rebuilt on the next force evaluation after m_packed gains, loses or
    /// reorders springs. So one SpringSet's forces are not evaluated from two
    /// threads at once (each procedure loop owns its colon).
    mutable SpringGather m_gather;
    mutable bool m_gatherStale = true;
    /// maxTensileStrain()'s springs (those of its family with a length), in
    /// the springs' order, rebuilt when the springs or the family asked for
    /// change: the loop asks for the wall's strain every step.
    struct StrainSpring {
        int i, j;
        double rest;      ///< m
        double invRest2;  ///< 1/m^2
    };
    mutable std::vector<StrainSpring> m_strainSprings;
    mutable std::vector<double> m_stretch2;  ///< per strain spring: (l / L)^2 as rounded, scratch
    mutable SpringFamily m_strainFamily = SpringFamily::Structural;
    mutable bool m_strainStale = true;
    void repack();
    [[nodiscard]] PackedSpring packed(size_t e) const;
    /// One active spring of the frozen system: its block of h D + h^2 K+ is
    /// along I + across u u^T (see linearize).
    struct LinearBlock {
        int i, j;
        double ux, uy, uz;
        double along, across;
    };
    std::vector<LinearBlock> m_linear;
};

}  // namespace colonosim::physics
