#pragma once
/// \file
/// Zero-rest-length springs from nodes to fixed points in the world: the
/// retroperitoneal binding of fixed colon segments and adhesions.
///   f_i = -k_i (x_i - a_i) - c_i v_i,   K_ii = -k_i I,   D_ii = -c_i I.

#include "simcore/physics/AwakeEntries.h"
#include "simcore/physics/ForceTerm.h"

#include <string>

namespace colonosim::physics {

class AnchorSprings final : public ForceTerm {
public:
    explicit AnchorSprings(std::string name = "anchors") : m_name(std::move(name)) {}

    /// k in N/m, c in N s/m; returns the anchor's index.
    int add(int node, const Eigen::Vector3d& anchor, double stiffness, double damping);
    [[nodiscard]] int numAnchors() const { return static_cast<int>(m_node.size()); }
    [[nodiscard]] int node(int a) const { return m_node[static_cast<size_t>(a)]; }

    [[nodiscard]] std::string_view name() const override { return m_name; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions& x, const Velocities& v, Forces& f) const override;
    void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const Positions& x, const Eigen::Matrix3Xd& dv,
                           Eigen::Matrix3Xd& df) const override;
    void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const override;
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override
    {
        m_awake.rebuild(m_node, awake);
    }
    [[nodiscard]] double potentialEnergy(const Positions& x) const override;

private:
    std::string m_name;
    std::vector<int> m_node;
    std::vector<Eigen::Vector3d> m_anchor;
    std::vector<double> m_k;
    std::vector<double> m_c;
    AwakeEntries m_awake;  ///< anchors whose node is awake (the force sums)
};

}  // namespace colonosim::physics
