#include "dgwarp/graph/coincident_points.hpp"

#include <gtest/gtest.h>

using namespace dgwarp;

TEST(GraphCoincident, GroupsEqualPointsByFirstMemberKeepingAllIds) {
    // Points 0..5 in 2D; list positions k pick nodes: 3 and 5 equal node 0's point, 4 equals node 1's.
    const std::vector<double> pts = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, -0.0, 1};
    const std::vector<NodeId> nodes = {0, 1, 2, 3, 4, 5, 6};  // node 6 = (-0, 1) equals node 2
    const CoincidentGroups g = group_coincident_points(2, pts, nodes);
    ASSERT_EQ(g.size(), 3u);
    EXPECT_EQ(g.offsets, (std::vector<std::int32_t>{0, 3, 5, 7}));
    EXPECT_EQ(g.members, (std::vector<std::int32_t>{0, 3, 5, 1, 4, 2, 6}));
}

TEST(GraphCoincident, DistinctPointsAreSingletonsInListOrder) {
    const std::vector<double> pts = {5, 5, 5, 1, 2, 3, 1, 2, 4};
    const std::vector<NodeId> nodes = {2, 0, 1};
    const CoincidentGroups g = group_coincident_points(3, pts, nodes);
    ASSERT_EQ(g.size(), 3u);
    EXPECT_EQ(g.members, (std::vector<std::int32_t>{0, 1, 2}));
}
