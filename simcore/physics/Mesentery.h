#pragma once
/// \file
/// The mesentery that hangs a mobile colon segment from the posterior
/// abdominal wall: one tension-only, non-linearly stiffening tether per node,
/// from the node to its root r on the wall, with rest length L.
///
/// With l = |x - r|, u = (x - r)/l and stretch delta = l - L:
///   T(delta) = 0                                   for delta <= 0 (slack)
///   T(delta) = k delta (1 + (delta/delta_s)^2)      for 0 < delta <= delta_max
///   T(delta) = T(delta_max) + k_max (delta - delta_max) beyond,
/// with delta_s = eps_s L (stiffening strain), delta_max = eps_max L and
/// k_max = T'(delta_max) = k (1 + 3 eps_max^2/eps_s^2), so the tangent
/// stiffness never exceeds k_max and the stable step stays bounded.
/// Force on the node f = -(T + c u.v) u while taut; K = -[T' u u^T + (T/l)(I - u u^T)].
/// Soft tissue's exponential-like stiffening: White et al. (mesocolon 0.088 -
/// 6.858 MPa, failure stretch 1.77 - 3.18), reference/physical-parameters.md.

#include "simcore/physics/AwakeEntries.h"
#include "simcore/physics/ForceTerm.h"

namespace colonosim::physics {

class Mesentery final : public ForceTerm {
public:
    struct Law {
        double stiffness = 0.0;         ///< k, N/m (small-strain)
        double damping = 0.0;           ///< c, N s/m (while taut)
        double stiffeningStrain = 0.3;  ///< eps_s, 1
        double maxStrain = 0.77;        ///< eps_max, 1
    };

    int add(int node, const Eigen::Vector3d& root, double restLength, const Law& law);
    [[nodiscard]] int numTethers() const { return static_cast<int>(m_node.size()); }

    /// Tension (N) of a tether law at stretch delta (m), rest length L (m).
    [[nodiscard]] static double tension(const Law& law, double restLength, double delta);
    [[nodiscard]] static double tangentStiffness(const Law& law, double restLength, double delta);
    /// Largest strain among the tethers at positions x (1).
    [[nodiscard]] double maxStrain(const Positions& x) const;

    [[nodiscard]] std::string_view name() const override { return "mesentery"; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions& x, const Velocities& v, Forces& f) const override;
    void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv,
                           Eigen::Matrix3Xd& df) const override;
    void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const override;
    [[nodiscard]] double potentialEnergy(const Positions& x) const override;
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override
    {
        m_awake.rebuild(m_node, awake);
    }

private:
    std::vector<int> m_node;
    std::vector<Eigen::Vector3d> m_root;
    std::vector<double> m_rest;
    std::vector<double> m_invRest2;  ///< 1 / m_rest^2, 1/m^2 (maxStrain's screen)
    std::vector<Law> m_law;
    mutable std::vector<double> m_stretch2;  ///< maxStrain's scratch: (l / L)^2 per tether
    AwakeEntries m_awake;                    ///< tethers whose node is awake (the force sums)
};

}  // namespace colonosim::physics
