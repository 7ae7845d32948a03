// Mesentery::maxStrain() screens the tethers by their squared stretch and
// takes the strain (l - L) / L only of those near the largest: it gives the
// strain formula's bits over every tether, when two tethers tie within
// rounding, and 0 when every tether is slack.

#include "simcore/physics/Mesentery.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>

namespace colonosim::physics {
namespace {

constexpr int kNodes = 60;
const Mesentery::Law kLaw{40.0, 0.02, 0.3, 0.77};

/// The largest strain over the tethers, tether after tether, as Mesentery.h states it.
double transcription(const std::vector<int>& nodes, const std::vector<Eigen::Vector3d>& roots,
                     const std::vector<double>& rests, const Positions& x)
{
    double largest = 0.0;
    for (size_t t = 0; t < nodes.size(); ++t) {
        largest = std::max(largest, ((x.col(nodes[t]) - roots[t]).norm() - rests[t]) / rests[t]);
    }
    return largest;
}

std::uint64_t bits(double value)
{
    return std::bit_cast<std::uint64_t>(value);
}

TEST(Mesentery, TheLargestStrainIsTheFormulasBitForBit)
{
    std::mt19937_64 random(20261129);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Positions x(3, kNodes);
    for (Eigen::Index k = 0; k < x.size(); ++k) {
        x.data()[k] = 0.05 * unit(random);
    }
    Mesentery mesentery;
    std::vector<int> nodes;
    std::vector<Eigen::Vector3d> roots;
    std::vector<double> rests;
    const auto tether = [&](int node, const Eigen::Vector3d& root, double rest) {
        mesentery.add(node, root, rest, kLaw);
        nodes.push_back(node);
        roots.push_back(root);
        rests.push_back(rest);
    };
    for (int node = 0; node < 50; ++node) {
        const Eigen::Vector3d root(0.0, 0.0, -0.08);
        // Taut by up to 60%, or slack (rest longer than the tether).
        tether(node, root, (x.col(node) - root).norm() / (1.0 + 0.6 * unit(random)));
    }
    const double expected = transcription(nodes, roots, rests, x);
    EXPECT_GT(expected, 0.1);
    EXPECT_EQ(bits(mesentery.maxStrain(x)), bits(expected));

    // Two tethers stretched alike to within rounding, beyond every other.
    const Eigen::Vector3d along(0.3, -0.2, 0.9);
    x.col(55) = Eigen::Vector3d(0.01, 0.0, 0.0);
    x.col(56) = Eigen::Vector3d(0.0, 0.02, 0.0);
    tether(55, x.col(55) - along, 0.25 * along.norm());
    tether(56, x.col(56) - along * (1.0 + 1e-15), 0.25 * along.norm());
    const double tied = transcription(nodes, roots, rests, x);
    EXPECT_GT(tied, 2.9);
    EXPECT_EQ(bits(mesentery.maxStrain(x)), bits(tied));

    // Every tether slack.
    Mesentery slack;
    slack.add(0, Eigen::Vector3d::Zero(), 1.01 * x.col(0).norm(), kLaw);
    slack.add(1, Eigen::Vector3d::Zero(), x.col(1).norm(), kLaw);
    EXPECT_EQ(bits(slack.maxStrain(x)),
              bits(transcription({0, 1}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                                 {1.01 * x.col(0).norm(), x.col(1).norm()}, x)));
}

}  // namespace
}  // namespace colonosim::physics
