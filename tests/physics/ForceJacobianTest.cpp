// Every force term and its Jacobians against central finite differences
// (SOFA's force-field test habit). Tolerance: 1e-6 relative to the largest
// entry of the product; central differences with eps = 1e-7 m have a
// truncation error of order eps^2 |f'''| and a round-off of order
// 1e-16 |f| / eps, both far below it for these magnitudes.

#include "simcore/contact/WallContactForce.h"
#include "simcore/physics/AnchorSprings.h"
#include "simcore/physics/Gravity.h"
#include "simcore/physics/InsufflationPressure.h"
#include "simcore/physics/Mesentery.h"
#include "simcore/physics/SpringSet.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <random>

namespace colonosim::physics {
namespace {

struct TermCase {
    const char* label;
    std::function<std::unique_ptr<ForceTerm>(const Positions& rest)> make;
    double displacement;  ///< amplitude of the random state around rest, m
};

void PrintTo(const TermCase& c, std::ostream* out)
{
    *out << c.label;
}

Positions restPositions()
{
    Positions x(3, 5);
    x << 0.00, 0.010, 0.000, 0.012, 0.006,  //
        0.00, 0.000, 0.011, 0.009, 0.004,   //
        0.00, 0.001, -0.002, 0.003, 0.008;
    return x;
}

std::vector<TermCase> termCases()
{
    return {
        {"stretched_springs",
         [](const Positions& x) {
             auto s = std::make_unique<SpringSet>();
             s->add(0, 1, 0.8 * (x.col(1) - x.col(0)).norm(), 120.0, 0.3);
             s->add(1, 3, 0.9 * (x.col(3) - x.col(1)).norm(), 80.0, 0.1);
             s->add(2, 4, 0.7 * (x.col(4) - x.col(2)).norm(), 200.0, 0.05);
             return s;
         },
         1e-3},
        {"compressed_springs",
         [](const Positions& x) {
             auto s = std::make_unique<SpringSet>();
             s->add(0, 2, 1.3 * (x.col(2) - x.col(0)).norm(), 150.0, 0.2);
             s->add(3, 4, 1.6 * (x.col(4) - x.col(3)).norm(), 60.0, 0.2);
             return s;
         },
         1e-3},
        {"springs_with_transverse_damping",
         [](const Positions& x) {
             auto s = std::make_unique<SpringSet>();
             s->setTransverseDamping(0.7);
             s->add(0, 1, 0.8 * (x.col(1) - x.col(0)).norm(), 120.0, 0.3);
             s->add(0, 2, 1.3 * (x.col(2) - x.col(0)).norm(), 150.0, 0.2);
             s->add(3, 4, (x.col(4) - x.col(3)).norm(), 60.0, 0.4);
             return s;
         },
         1e-3},
        {"mesentery_taut",
         [](const Positions&) {
             auto m = std::make_unique<Mesentery>();
             const Mesentery::Law law{40.0, 0.02, 0.3, 0.77};
             m->add(1, Eigen::Vector3d(0.01, 0.06, 0.0), 0.045, law);
             m->add(3, Eigen::Vector3d(0.01, 0.07, 0.0), 0.050, law);
             return m;
         },
         1e-3},
        {"mesentery_beyond_max_strain",
         [](const Positions&) {
             auto m = std::make_unique<Mesentery>();
             const Mesentery::Law law{40.0, 0.02, 0.3, 0.5};
             m->add(2, Eigen::Vector3d(0.0, 0.09, 0.0), 0.04, law);
             return m;
         },
         1e-3},
        {"anchors",
         [](const Positions&) {
             auto a = std::make_unique<AnchorSprings>();
             a->add(0, Eigen::Vector3d(0.001, 0.0, 0.002), 300.0, 0.4);
             a->add(4, Eigen::Vector3d(0.0, 0.01, 0.0), 50.0, 0.0);
             return a;
         },
         1e-3},
        {"insufflation",
         [](const Positions&) {
             return std::make_unique<InsufflationPressure>(
                 std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}}, 2000.0);
         },
         1e-3},
        {"scope_contact",
         [](const Positions& x) {
             // Two contacts pressing the wall outward by about 2-3 mm (the
             // scope axis 4 mm from the wall for a 6.5 mm radius).
             static geometry::TriangleMesh mesh;
             mesh.vertices = x;
             mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
             auto term = std::make_unique<contact::WallContactForce>(mesh, contact::ContactParameters{}, 5);
             std::vector<contact::ScopeContact> contacts(2);
             std::vector<Eigen::Vector3d> axis;
             for (int k = 0; k < 2; ++k) {
                 contacts[static_cast<size_t>(k)].triangle = k;
                 contacts[static_cast<size_t>(k)].barycentric = Eigen::Vector3d(0.2, 0.3, 0.5);
                 contacts[static_cast<size_t>(k)].normal = Eigen::Vector3d(0.1, 0.2, 1.0).normalized();
                 const auto& tri = mesh.triangles[static_cast<size_t>(k)];
                 const Eigen::Vector3d wall = 0.2 * x.col(tri[0]) + 0.3 * x.col(tri[1]) + 0.5 * x.col(tri[2]);
                 axis.push_back(wall + 0.004 * contacts[static_cast<size_t>(k)].normal);
             }
             term->setContacts(contacts, axis, 0.0065);
             return term;
         },
         5e-4},
        {"gravity",
         [](const Positions&) {
             return std::make_unique<Gravity>(Eigen::VectorXd::Constant(5, 3e-4),
                                              Eigen::Vector3d(9.81, 0, 0));
         },
         1e-3},
    };
}

class ForceJacobian : public ::testing::TestWithParam<TermCase> {};

TEST_P(ForceJacobian, StiffnessMatchesFiniteDifferences)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const Positions rest = restPositions();
    const auto term = GetParam().make(rest);
    for (int trial = 0; trial < 5; ++trial) {
        Positions x = rest;
        Eigen::Matrix3Xd dx(3, x.cols());
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            x.data()[i] += GetParam().displacement * uniform(random);
            dx.data()[i] = uniform(random);
        }
        constexpr double eps = 1e-7;
        Forces fPlus = Forces::Zero(3, x.cols());
        Forces fMinus = Forces::Zero(3, x.cols());
        term->addForce(x + eps * dx, fPlus);
        term->addForce(x - eps * dx, fMinus);
        const Eigen::Matrix3Xd numeric = (fPlus - fMinus) / (2.0 * eps);
        Eigen::Matrix3Xd analytic = Eigen::Matrix3Xd::Zero(3, x.cols());
        term->addStiffnessProduct(x, dx, analytic);
        const double scale = std::max(1.0, numeric.cwiseAbs().maxCoeff());
        EXPECT_LT((numeric - analytic).cwiseAbs().maxCoeff(), 1e-6 * scale)
            << GetParam().label << " trial " << trial << "\nnumeric\n"
            << numeric << "\nanalytic\n"
            << analytic;
    }
}

TEST_P(ForceJacobian, DampingMatchesFiniteDifferences)
{
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const Positions rest = restPositions();
    const auto term = GetParam().make(rest);
    Positions x = rest;
    Velocities v(3, x.cols());
    Eigen::Matrix3Xd dv(3, x.cols());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        x.data()[i] += GetParam().displacement * uniform(random);
        v.data()[i] = 0.1 * uniform(random);
        dv.data()[i] = uniform(random);
    }
    constexpr double eps = 1e-6;
    Forces fPlus = Forces::Zero(3, x.cols());
    Forces fMinus = Forces::Zero(3, x.cols());
    term->addDampingForce(x, v + eps * dv, fPlus);
    term->addDampingForce(x, v - eps * dv, fMinus);
    const Eigen::Matrix3Xd numeric = (fPlus - fMinus) / (2.0 * eps);
    Eigen::Matrix3Xd analytic = Eigen::Matrix3Xd::Zero(3, x.cols());
    term->addDampingProduct(x, dv, analytic);
    EXPECT_LT((numeric - analytic).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, numeric.cwiseAbs().maxCoeff()))
        << GetParam().label;
}

TEST_P(ForceJacobian, CombinedPassEqualsSeparatePasses)
{
    const Positions rest = restPositions();
    const auto term = GetParam().make(rest);
    Positions x = rest;
    x.col(1) += Eigen::Vector3d(1e-3, -2e-3, 5e-4);
    const Velocities v = Velocities::Constant(3, x.cols(), 0.05);
    Forces separate = Forces::Zero(3, x.cols());
    term->addForce(x, separate);
    term->addDampingForce(x, v, separate);
    Forces combined = Forces::Zero(3, x.cols());
    term->addForceAndDamping(x, v, combined);
    EXPECT_LT((separate - combined).cwiseAbs().maxCoeff(), 1e-12) << GetParam().label;
}

TEST_P(ForceJacobian, ElasticForceIsMinusEnergyGradient)
{
    const Positions rest = restPositions();
    const auto term = GetParam().make(rest);
    if (!term->hasSymmetricJacobian()) {
        // Follower pressure loads have no potential; their Jacobian is checked above.
        EXPECT_EQ(term->potentialEnergy(rest), 0.0);
        return;
    }
    Positions x = rest;
    x.col(2) += Eigen::Vector3d(2e-3, 1e-3, -1e-3);
    Forces f = Forces::Zero(3, x.cols());
    term->addForce(x, f);
    constexpr double eps = 1e-7;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        Positions plus = x;
        Positions minus = x;
        plus.data()[i] += eps;
        minus.data()[i] -= eps;
        const double gradient = (term->potentialEnergy(plus) - term->potentialEnergy(minus)) / (2.0 * eps);
        EXPECT_NEAR(-gradient, f.data()[i], 1e-6 * std::max(1.0, std::abs(f.data()[i]))) << GetParam().label;
    }
}

INSTANTIATE_TEST_SUITE_P(AllTerms, ForceJacobian, ::testing::ValuesIn(termCases()),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(SpringSet, StiffnessBoundCoversTheBlockNorm)
{
    // The 3x3 block norm is k max(1, |1 - L/l|); the bound adds it twice per
    // end (diagonal and off-diagonal block).
    SpringSet springs;
    springs.add(0, 1, 0.01, 100.0, 0.5);
    Eigen::VectorXd kRow = Eigen::VectorXd::Zero(2);
    Eigen::VectorXd cRow = Eigen::VectorXd::Zero(2);
    Positions x = Positions::Zero(3, 2);
    x(0, 1) = 0.01;  // at rest length
    springs.addStiffnessBound(x, kRow, cRow);
    EXPECT_DOUBLE_EQ(kRow[0], 200.0);
    x(0, 1) = 0.002;  // compressed to L/5: transverse factor |1 - L/l| = 4
    kRow.setZero();
    springs.addStiffnessBound(x, kRow, cRow);
    EXPECT_DOUBLE_EQ(kRow[0], 800.0);
    EXPECT_DOUBLE_EQ(cRow[1], 2.0) << "two evaluations of 2c";
}

TEST(SpringSet, FrozenSystemProductEqualsTheSeparateProducts)
{
    // The implicit solve's frozen system (h D + h^2 K+) y must equal the two
    // products it replaces, stretched and compressed springs alike (a
    // compressed spring loses its transverse term in K+), also after the
    // active set changed.
    const Positions rest = restPositions();
    SpringSet springs;
    springs.add(0, 1, 0.8 * (rest.col(1) - rest.col(0)).norm(), 120.0, 0.3);
    springs.add(0, 2, 1.3 * (rest.col(2) - rest.col(0)).norm(), 150.0, 0.2);
    springs.add(1, 3, 0.9 * (rest.col(3) - rest.col(1)).norm(), 80.0, 0.1);
    springs.add(3, 4, 1.6 * (rest.col(4) - rest.col(3)).norm(), 60.0, 0.0);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const double h = 1e-3;
    for (const double transverse : {0.0, 0.6, 1.0}) {
        springs.setTransverseDamping(transverse);
        for (const std::vector<std::uint8_t>& awake :
             {std::vector<std::uint8_t>{1, 1, 1, 1, 1}, std::vector<std::uint8_t>{0, 0, 1, 0, 1}}) {
            springs.onActiveSetChanged(awake);
            Positions x = rest;
            Eigen::Matrix3Xd y(3, x.cols());
            for (Eigen::Index i = 0; i < x.size(); ++i) {
                x.data()[i] += 1e-3 * uniform(random);
                y.data()[i] = uniform(random);
            }
            Eigen::Matrix3Xd stiffness = Eigen::Matrix3Xd::Zero(3, x.cols());
            Eigen::Matrix3Xd damping = Eigen::Matrix3Xd::Zero(3, x.cols());
            springs.addDefiniteStiffnessProduct(x, y, stiffness);
            springs.addDampingProduct(x, y, damping);
            const Eigen::Matrix3Xd expected = h * damping + h * h * stiffness;
            ASSERT_TRUE(springs.linearize(x, h));
            Eigen::Matrix3Xd frozen = Eigen::Matrix3Xd::Zero(3, x.cols());
            springs.addSystemProduct(y, frozen);
            ASSERT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
            EXPECT_LT((frozen - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff())
                << "expected\n"
                << expected << "\nfrozen\n"
                << frozen;
        }
    }
}

TEST(SpringSet, TransverseDampingActsOnTheWholeRelativeVelocity)
{
    // Two nodes at rest length, one moving across the spring: damped only
    // along the spring (t = 0) nothing resists it; at t = 1 the damping is
    // c dv, a viscous tissue; in between, t c dv. Along the spring every t
    // gives c dv.
    SpringSet springs;
    springs.add(0, 1, 0.01, 100.0, 0.5);
    Positions x = Positions::Zero(3, 2);
    x(0, 1) = 0.01;
    Velocities across = Velocities::Zero(3, 2);
    across(1, 1) = 2.0;  // node 1 moves along y at 2 m/s
    Velocities along = Velocities::Zero(3, 2);
    along(0, 1) = 2.0;
    for (const double t : {0.0, 0.25, 1.0}) {
        springs.setTransverseDamping(t);
        Forces f = Forces::Zero(3, 2);
        springs.addForceAndDamping(x, across, f);
        EXPECT_NEAR(f(1, 0), t * 0.5 * 2.0, 1e-12) << "t = " << t;
        EXPECT_NEAR(f(1, 1), -t * 0.5 * 2.0, 1e-12) << "t = " << t;
        f.setZero();
        springs.addForceAndDamping(x, along, f);
        EXPECT_NEAR(f(0, 0), 0.5 * 2.0, 1e-12) << "t = " << t;
        EXPECT_NEAR(f(1, 0), 0.0, 1e-12) << "t = " << t;
    }
    EXPECT_THROW(springs.setTransverseDamping(1.5), std::invalid_argument);
    EXPECT_THROW(springs.setTransverseDamping(-0.1), std::invalid_argument);
}

TEST(SpringSet, RemoveKeepsTheOtherSprings)
{
    SpringSet springs;
    springs.add(0, 1, 0.01, 10.0, 0.0);
    springs.add(1, 2, 0.02, 20.0, 0.0);
    springs.add(2, 3, 0.03, 30.0, 0.0);
    springs.remove(0);
    ASSERT_EQ(springs.numSprings(), 2);
    EXPECT_EQ(springs.nodeA(0), 2);
    EXPECT_DOUBLE_EQ(springs.stiffness(0), 30.0);
    EXPECT_EQ(springs.nodeA(1), 1);
}

TEST(Mesentery, SlackTetherPullsNothingAndStiffensWhenStretched)
{
    const Mesentery::Law law{10.0, 0.0, 0.2, 0.5};
    EXPECT_EQ(Mesentery::tension(law, 0.05, -0.01), 0.0);
    const double small = Mesentery::tangentStiffness(law, 0.05, 1e-6);
    const double large = Mesentery::tangentStiffness(law, 0.05, 0.2 * 0.05);
    EXPECT_NEAR(small, 10.0, 1e-3);
    EXPECT_NEAR(large, 40.0, 1e-9) << "at the stiffening strain the tangent stiffness has quadrupled";
    EXPECT_DOUBLE_EQ(Mesentery::tangentStiffness(law, 0.05, 1.0),
                     Mesentery::tangentStiffness(law, 0.05, 0.025))
        << "no further stiffening beyond the maximum strain";
}

}  // namespace
}  // namespace colonosim::physics
