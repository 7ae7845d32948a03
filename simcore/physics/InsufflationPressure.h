#pragma once
/// \file
/// Insufflation: a uniform gauge pressure p inside the lumen pushes each wall
/// triangle outward. With the triangle's area vector a = (x1 - x0) x (x2 - x0) / 2
/// (pointing out of the lumen), each of its three nodes receives f = p a / 3.
/// Differential: da = [(dx1 - dx0) x (x2 - x0) + (x1 - x0) x (dx2 - dx0)] / 2.
/// The Jacobian is not symmetric, so the implicit solver treats this force
/// explicitly. Follower loads have no potential; potentialEnergy() is 0.
/// Range: 9-57 mmHg with the tip free during colonoscopy (reference table).
/// addForce() runs in two passes, with the bits of adding the triangles into
/// their nodes one after the other: every active triangle's nodal force (four
/// at once in AVX2's lanes where the processor has them, each lane doing the
/// scalar form's IEEE operations), then each node's triangles summed in the
/// triangles' order (NodeGather.h; tests/physics/PressureKernelTest.cpp).

#include "simcore/physics/ForceTerm.h"
#include "simcore/physics/NodeGather.h"

#include <array>

namespace colonosim::physics {

class InsufflationPressure final : public ForceTerm {
public:
    /// `triangles` oriented with normals out of the lumen; p in Pa.
    InsufflationPressure(std::vector<std::array<int, 3>> triangles, double pressure);

    void setPressure(double pressure) { m_pressure = pressure; }
    [[nodiscard]] double pressure() const { return m_pressure; }

    [[nodiscard]] std::string_view name() const override { return "insufflation"; }
    void addForce(const Positions& x, Forces& f) const override;
    void addDampingForce(const Positions&, const Velocities&, Forces&) const override {}
    void addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                             Eigen::Matrix3Xd& df) const override;
    void addDampingProduct(const Positions&, const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&) const override {}
    void addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow, Eigen::VectorXd& cRow) const override;
    [[nodiscard]] double potentialEnergy(const Positions&) const override { return 0.0; }
    [[nodiscard]] bool hasSymmetricJacobian() const override { return false; }
    void onActiveSetChanged(const std::vector<std::uint8_t>& awake) override;

private:
    std::vector<std::array<int, 3>> m_triangles;
    std::vector<int> m_active;
    double m_pressure;
    NodeGather m_gather;         ///< the active triangles' nodes
    std::vector<int> m_corners;  ///< their corners as m_gather is built from (kept for its storage)
    /// The first pass's nodal force per active triangle, N (scratch: one
    /// object's forces are not evaluated from two threads at once).
    mutable std::vector<double> m_fx, m_fy, m_fz;
};

}  // namespace colonosim::physics
