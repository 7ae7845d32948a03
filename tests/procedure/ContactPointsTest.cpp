// Where the scope meets the wall: the nodes, and points inside each element
// numbered from the base (ContactPoints.h).

#include "simcore/procedure/ContactPoints.h"

#include <gtest/gtest.h>

namespace {

using colonosim::procedure::ContactPoints;

TEST(ContactPoints, TheNodesAloneAreThePointsByDefault)
{
    const ContactPoints points;
    EXPECT_EQ(points.count(0), 0);
    EXPECT_EQ(points.count(5), 5);
    for (int p = 0; p < 5; ++p) {
        EXPECT_EQ(points.node(p), p);
        EXPECT_EQ(points.share(p), 0.0);
        EXPECT_EQ(points.joints(p), p);
    }
}

TEST(ContactPoints, InnerPointsFollowTheirElementsBaseSideNode)
{
    const ContactPoints points{3};  // two points inside each element
    EXPECT_EQ(points.count(1), 1);
    EXPECT_EQ(points.count(4), 10);  // 4 nodes, 3 elements
    // Point 7 is node 2's element's first inner point, a third of the way.
    EXPECT_EQ(points.node(7), 2);
    EXPECT_DOUBLE_EQ(points.share(7), 1.0 / 3.0);
    EXPECT_EQ(points.joints(7), 3) << "node 2's own joint turns it";
    EXPECT_EQ(points.joints(6), 2) << "node 2 itself";

    Eigen::Matrix3Xd nodes(3, 4);
    nodes << 0.0, 0.03, 0.03, 0.06, 0.0, 0.0, 0.03, 0.03, 0.0, 0.0, 0.0, 0.0;
    Eigen::Matrix3Xd at;
    points.interpolate(nodes, at);
    ASSERT_EQ(at.cols(), 10);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(at.col(3 * i), nodes.col(i)) << "node " << i << " is itself, bit for bit";
    }
    EXPECT_TRUE(at.col(4).isApprox(Eigen::Vector3d(0.03, 0.01, 0.0))) << "node 1's element, a third";
    EXPECT_TRUE(at.col(5).isApprox(Eigen::Vector3d(0.03, 0.02, 0.0))) << "two thirds";
    EXPECT_TRUE(at.col(7).isApprox(Eigen::Vector3d(0.04, 0.03, 0.0))) << "node 2's element, a third";
    const std::vector<Eigen::Vector3d> list{nodes.col(0), nodes.col(1), nodes.col(2), nodes.col(3)};
    for (int p = 0; p < 10; ++p) {
        EXPECT_EQ(points.at(list, p), at.col(p).eval()) << "point " << p;
    }
}

}  // namespace
