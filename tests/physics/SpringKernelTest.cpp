// SpringSet::addForceAndDamping() runs over a packed copy of the active
// springs, four at a time in AVX2's lanes where the processor has them
// (SpringKernel.h). These tests hold it, and the kernel's one-spring path, to
// the bits of the per-spring expression (transcribed below with Eigen, as
// SpringSet.h states it), through every change that repacks the springs: the
// active set, a stiffness, the transverse damping and a removal. A
// zero-length spring and a count that leaves springs past the last four are
// included.

#include "simcore/physics/SpringKernel.h"
#include "simcore/physics/SpringSet.h"
#include "tests/physics/SameBits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace colonosim::physics {
namespace {

constexpr int kNodes = 300;

/// The force of every active spring, one after the other in index order, as
/// SpringSet.h defines it: k (l - L) u + c [(1 - t) u u^T + t I] (v_j - v_i).
Forces transcription(const SpringSet& springs, const std::vector<std::uint8_t>& awake, const Positions& x,
                     const Velocities& v)
{
    Forces f = Forces::Zero(3, x.cols());
    const double t = springs.transverseDamping();
    for (int s = 0; s < springs.numSprings(); ++s) {
        const int i = springs.nodeA(s);
        const int j = springs.nodeB(s);
        if (!awake.empty() && awake[static_cast<size_t>(i)] == 0 && awake[static_cast<size_t>(j)] == 0) {
            continue;
        }
        const Eigen::Vector3d d = x.col(j) - x.col(i);
        const double l2 = d.squaredNorm();
        if (l2 < SpringSet::kMinLength * SpringSet::kMinLength) {
            continue;
        }
        const double invL = 1.0 / std::sqrt(l2);
        const Eigen::Vector3d dv = v.col(j) - v.col(i);
        const double speed = d.dot(dv) * invL;
        const double tension = springs.stiffness(s) * (l2 * invL - springs.restLength(s)) +
                               (1.0 - t) * springs.damping(s) * speed;
        const Eigen::Vector3d fs = (tension * invL) * d + (t * springs.damping(s)) * dv;
        f.col(i) += fs;
        f.col(j) -= fs;
    }
    return f;
}

void expectSameBits(const Forces& expected, const Forces& actual)
{
    ASSERT_EQ(expected.cols(), actual.cols());
    EXPECT_EQ(testing::differingBits(expected, actual), 0) << "of " << expected.size() << " force components";
}

class SpringKernel : public ::testing::Test {
protected:
    void SetUp() override
    {
        std::mt19937_64 random(20261128);
        std::uniform_real_distribution<double> position(-0.05, 0.05);
        std::uniform_real_distribution<double> velocity(-0.2, 0.2);
        std::uniform_int_distribution<int> node(0, kNodes - 1);
        std::uniform_real_distribution<double> factor(0.5, 1.5);
        x = Positions(3, kNodes);
        v = Velocities(3, kNodes);
        for (Eigen::Index k = 0; k < x.size(); ++k) {
            x.data()[k] = position(random);
            v.data()[k] = velocity(random);
        }
        x.col(7) = x.col(8);  // spring 0 below has no length
        springs.setTransverseDamping(0.35);
        springs.add(7, 8, 0.01, 100.0, 0.2);
        for (int s = 1; s < 1001; ++s) {
            // Spring 1 ends at the last node: the four-lane path reads it with
            // a masked load that must stay inside x and v (the sanitizer build checks).
            int i = s == 1 ? kNodes - 1 : node(random);
            int j = node(random);
            while (j == i) {
                j = node(random);
            }
            const double length = (x.col(j) - x.col(i)).norm();
            springs.add(i, j, factor(random) * length, 50.0 * factor(random), 0.1 * factor(random),
                        s % 3 == 0 ? SpringFamily::Bending : SpringFamily::Structural);
        }
    }

    Forces kernel() const
    {
        Forces f = Forces::Zero(3, kNodes);
        springs.addForceAndDamping(x, v, f);
        return f;
    }

    SpringSet springs;
    Positions x;
    Velocities v;
};

TEST_F(SpringKernel, AllAwakeGivesTheBitsOfThePerSpringExpression)
{
    ASSERT_EQ(springs.numSprings() % 4, 1);
    expectSameBits(transcription(springs, {}, x, v), kernel());
}

TEST_F(SpringKernel, OneSpringAtATimeGivesTheSameBits)
{
    std::vector<PackedSpring> packed;
    const double t = springs.transverseDamping();
    for (int s = 0; s < springs.numSprings(); ++s) {
        packed.push_back({springs.nodeA(s), springs.nodeB(s), springs.restLength(s), springs.stiffness(s),
                          (1.0 - t) * springs.damping(s), t * springs.damping(s)});
    }
    Forces widest = Forces::Zero(3, kNodes);
    Forces one = Forces::Zero(3, kNodes);
    SpringGather gather;
    gather.build(packed);
    addSpringForces(packed, gather, x.data(), v.data(), widest.data(), SpringLanes::Widest);
    addSpringForces(packed, gather, x.data(), v.data(), one.data(), SpringLanes::One);
    expectSameBits(transcription(springs, {}, x, v), one);
    expectSameBits(one, widest);
}

TEST_F(SpringKernel, PartlyAwakeGivesTheBitsOfTheActiveSpringsAlone)
{
    std::vector<std::uint8_t> awake(kNodes, 0);
    for (int k = 0; k < kNodes; k += 3) {
        awake[static_cast<size_t>(k)] = 1;
    }
    springs.onActiveSetChanged(awake);
    const Forces f = kernel();
    expectSameBits(transcription(springs, awake, x, v), f);
    // Asleep springs are left out: the forces differ from the whole set's.
    EXPECT_GT((f - transcription(springs, {}, x, v)).norm(), 0.0);
}

TEST_F(SpringKernel, ChangedStiffnessDampingAndRemovalAreRepacked)
{
    springs.setStiffness(5, 3.0 * springs.stiffness(5), 2.0 * springs.damping(5));
    springs.setStiffness(600, 0.0, 0.0);
    expectSameBits(transcription(springs, {}, x, v), kernel());
    springs.setTransverseDamping(1.0);
    expectSameBits(transcription(springs, {}, x, v), kernel());
    springs.remove(17);
    ASSERT_EQ(springs.numSprings() % 4, 0);
    expectSameBits(transcription(springs, {}, x, v), kernel());
    std::vector<std::uint8_t> awake(kNodes, 1);
    awake[3] = 0;
    springs.onActiveSetChanged(awake);
    springs.add(3, 4, 0.02, 10.0, 0.01);  // awake through node 4
    expectSameBits(transcription(springs, awake, x, v), kernel());
}

/// The largest tensile strain of `family`, spring after spring, as SpringSet.h states it.
double strainTranscription(const SpringSet& springs, const Positions& x, SpringFamily family)
{
    double largest = 0.0;
    for (int s = 0; s < springs.numSprings(); ++s) {
        if (springs.family(s) == family && springs.restLength(s) > 0.0) {
            const double l = (x.col(springs.nodeB(s)) - x.col(springs.nodeA(s))).norm();
            largest = std::max(largest, (l - springs.restLength(s)) / springs.restLength(s));
        }
    }
    return largest;
}

// maxTensileStrain() screens the springs by their squared stretch and takes
// the strain only of those near the largest: it gives the strain formula's
// bits, for each family, after the springs change, when two springs tie
// within rounding, and 0 when nothing is stretched.
TEST_F(SpringKernel, TheLargestTensileStrainIsTheFormulasBitForBit)
{
    for (const SpringFamily family : {SpringFamily::Structural, SpringFamily::Bending}) {
        const double expected = strainTranscription(springs, x, family);
        EXPECT_GT(expected, 0.1);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(springs.maxTensileStrain(x, family)),
                  std::bit_cast<std::uint64_t>(expected));
    }
    EXPECT_EQ(springs.maxTensileStrain(x, SpringFamily::Shear), 0.0) << "no shear springs";

    // Two springs stretched alike to within rounding, above every other one:
    // the screen keeps both and the formula picks, as it did alone.
    const Eigen::Vector3d along(0.3, -0.2, 0.9);
    x.col(10) = Eigen::Vector3d::Zero();
    x.col(11) = along;
    x.col(12) = Eigen::Vector3d(0.01, 0.0, 0.0);
    x.col(13) = x.col(12) + along * (1.0 + 1e-15);
    const double rest = 0.25 * along.norm();
    springs.add(10, 11, rest, 10.0, 0.0);
    springs.add(12, 13, rest, 10.0, 0.0);
    const double tied = strainTranscription(springs, x, SpringFamily::Structural);
    EXPECT_GT(tied, 2.9);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(springs.maxTensileStrain(x, SpringFamily::Structural)),
              std::bit_cast<std::uint64_t>(tied));
    springs.remove(springs.numSprings() - 1);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(springs.maxTensileStrain(x, SpringFamily::Structural)),
              std::bit_cast<std::uint64_t>(strainTranscription(springs, x, SpringFamily::Structural)));

    // Nothing stretched: every spring at or below its length.
    SpringSet slack;
    slack.add(0, 1, 1.01 * (x.col(1) - x.col(0)).norm(), 10.0, 0.0);
    slack.add(2, 3, (x.col(3) - x.col(2)).norm(), 10.0, 0.0);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(slack.maxTensileStrain(x, SpringFamily::Structural)),
              std::bit_cast<std::uint64_t>(strainTranscription(slack, x, SpringFamily::Structural)));
}

// addStiffnessBound() takes the transverse factor max(1, |1 - L/l|) (capped at
// 10) only for springs at most 0.51 of their rest length long, the factor
// being 1 for all others: its row sums are the formula's bits, for springs
// compressed past half their length, at half exactly, just around the screen's
// 0.51, stretched, and without length.
TEST_F(SpringKernel, TheStiffnessBoundIsTheFormulasBitForBit)
{
    const Eigen::Vector3d along(0.02, -0.01, 0.015);
    x.col(20) = Eigen::Vector3d::Zero();
    x.col(21) = along;
    for (const double ratio : {1.0 / 0.3, 1.0 / 0.05, 2.0, 1.0 / 0.509, 1.0 / 0.51, 1.0 / 0.511, 0.9}) {
        springs.add(20, 21, ratio * along.norm(), 40.0, 0.3);
    }
    Eigen::VectorXd kExpected = Eigen::VectorXd::Zero(kNodes);
    Eigen::VectorXd cExpected = Eigen::VectorXd::Zero(kNodes);
    for (int s = 0; s < springs.numSprings(); ++s) {
        const double l = (x.col(springs.nodeB(s)) - x.col(springs.nodeA(s))).norm();
        const double factor = l > SpringSet::kMinLength
                                  ? std::min(std::max(1.0, std::abs(1.0 - springs.restLength(s) / l)), 10.0)
                                  : 1.0;
        for (const int n : {springs.nodeA(s), springs.nodeB(s)}) {
            kExpected[n] += 2.0 * factor * springs.stiffness(s);
            cExpected[n] += 2.0 * springs.damping(s);
        }
    }
    Eigen::VectorXd kRow = Eigen::VectorXd::Zero(kNodes);
    Eigen::VectorXd cRow = Eigen::VectorXd::Zero(kNodes);
    springs.addStiffnessBound(x, kRow, cRow);
    EXPECT_GT(kRow[20], 2.0 * 10.0 * 40.0) << "the capped factor of the spring at 0.05 of its length is in";
    EXPECT_EQ(testing::differingBits(kExpected, kRow), 0) << "of " << kNodes << " stiffness row sums";
    EXPECT_EQ(testing::differingBits(cExpected, cRow), 0) << "of " << kNodes << " damping row sums";
}

}  // namespace
}  // namespace colonosim::physics
