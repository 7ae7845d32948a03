// InsufflationPressure::addForce() computes every active triangle's nodal
// force first (four at a time in AVX2's lanes where the processor has them)
// and then sums each node's triangles in the triangles' order (NodeGather.h).
// These tests hold it to the bits of the per-triangle expression, added into
// the nodes one triangle after the other (transcribed below with Eigen, as
// InsufflationPressure.h states it), for every triangle awake and for a
// partial active set, with a count that leaves triangles past the last four.

#include "simcore/physics/InsufflationPressure.h"
#include "tests/physics/SameBits.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace colonosim::physics {
namespace {

constexpr int kNodes = 400;
constexpr int kTriangles = 1003;      // three past the last group of four
constexpr double kPressure = 2666.0;  // Pa, 20 mmHg

/// Each triangle with an awake corner adds p/6 (x1 - x0) x (x2 - x0) to each
/// of its corners, triangle after triangle.
Forces transcription(const std::vector<std::array<int, 3>>& triangles, const std::vector<std::uint8_t>& awake,
                     const Positions& x, double pressure)
{
    Forces f = Forces::Zero(3, x.cols());
    for (const auto& tri : triangles) {
        const bool any = awake.empty() || awake[static_cast<size_t>(tri[0])] ||
                         awake[static_cast<size_t>(tri[1])] || awake[static_cast<size_t>(tri[2])];
        if (!any) {
            continue;
        }
        const Eigen::Vector3d x0 = x.col(tri[0]);
        const Eigen::Vector3d fn = pressure / 6.0 * (x.col(tri[1]) - x0).cross(x.col(tri[2]) - x0);
        for (const int node : tri) {
            f.col(node) += fn;
        }
    }
    return f;
}

using testing::differingBits;

class PressureKernel : public ::testing::Test {
protected:
    void SetUp() override
    {
        std::mt19937_64 random(20261129);
        std::uniform_real_distribution<double> position(-0.05, 0.05);
        std::uniform_int_distribution<int> node(0, kNodes - 1);
        x = Positions(3, kNodes);
        for (Eigen::Index k = 0; k < x.size(); ++k) {
            x.data()[k] = position(random);
        }
        for (int t = 0; t < kTriangles; ++t) {
            // Triangle 0 has the last node as a corner: the four-lane path reads
            // it with a masked load that must stay inside x (the sanitizer build checks).
            std::array<int, 3> tri{t == 0 ? kNodes - 1 : node(random), node(random), node(random)};
            while (tri[1] == tri[0]) {
                tri[1] = node(random);
            }
            while (tri[2] == tri[0] || tri[2] == tri[1]) {
                tri[2] = node(random);
            }
            triangles.push_back(tri);
        }
    }

    [[nodiscard]] Forces kernel(const InsufflationPressure& pressure) const
    {
        Forces f = Forces::Zero(3, kNodes);
        pressure.addForce(x, f);
        return f;
    }

    std::vector<std::array<int, 3>> triangles;
    Positions x;
};

TEST_F(PressureKernel, AllAwakeGivesTheBitsOfThePerTriangleExpression)
{
    const InsufflationPressure pressure(triangles, kPressure);
    const Forces expected = transcription(triangles, {}, x, kPressure);
    EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(differingBits(expected, kernel(pressure)), 0)
        << "of " << expected.size() << " force components";
}

TEST_F(PressureKernel, APartialActiveSetAndANewPressureGiveTheSameBits)
{
    InsufflationPressure pressure(triangles, kPressure);
    std::vector<std::uint8_t> awake(kNodes, 0);
    for (int n = 0; n < kNodes; n += 7) {
        awake[static_cast<size_t>(n)] = 1;
    }
    pressure.onActiveSetChanged(awake);
    pressure.setPressure(1.5 * kPressure);
    const Forces expected = transcription(triangles, awake, x, 1.5 * kPressure);
    const Forces actual = kernel(pressure);
    EXPECT_EQ(differingBits(expected, actual), 0) << "of " << expected.size() << " force components";
    // A sleeping triangle adds nothing: a node no awake triangle touches keeps no force.
    EXPECT_GT(differingBits(transcription(triangles, {}, x, 1.5 * kPressure), actual), 0);
}

// addStiffnessBound() takes a triangle's longest edge as the root of its
// largest squared edge, with the bits of the largest of the three norms.
TEST_F(PressureKernel, TheStiffnessBoundIsTheFormulasBitForBit)
{
    const InsufflationPressure pressure(triangles, kPressure);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(kNodes);
    for (const auto& tri : triangles) {
        double longest = 0.0;
        for (int k = 0; k < 3; ++k) {
            longest = std::max(longest, (x.col(tri[(k + 1) % 3]) - x.col(tri[k])).norm());
        }
        for (const int node : tri) {
            expected[node] += 3.0 * std::abs(kPressure) / 6.0 * longest;
        }
    }
    Eigen::VectorXd kRow = Eigen::VectorXd::Zero(kNodes);
    Eigen::VectorXd cRow = Eigen::VectorXd::Zero(kNodes);
    pressure.addStiffnessBound(x, kRow, cRow);
    EXPECT_EQ(cRow.squaredNorm(), 0.0);
    EXPECT_EQ(differingBits(expected, kRow), 0) << "of " << kNodes << " stiffness row sums";
}

}  // namespace
}  // namespace colonosim::physics
