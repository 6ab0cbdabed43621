// NearestNode (nearest_node.hpp): nearest, k nearest and spacing against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dgwarp/graph/nearest_node.hpp"

using namespace dgwarp;

namespace {

// n random points in [0, 1]^dim, and every id.
std::vector<double> nearest_test_points(int dim, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> p(static_cast<std::size_t>(n) * dim);
    for (double& x : p) x = u(rng);
    return p;
}

std::vector<double> nearest_test_distances(int dim, const std::vector<double>& p, const double* x) {
    std::vector<double> d;
    for (std::size_t i = 0; i < p.size() / dim; ++i) {
        double s = 0;
        for (int k = 0; k < dim; ++k) s += (p[i * dim + k] - x[k]) * (p[i * dim + k] - x[k]);
        d.push_back(std::sqrt(s));
    }
    std::sort(d.begin(), d.end());
    return d;
}

}  // namespace

TEST(NearestNode, KNearestAreTheBruteForceOnesNearestFirst) {
    for (int dim : {2, 3}) {
        const std::vector<double> p = nearest_test_points(dim, 500, 3);
        std::vector<NodeId> ids(500);
        for (int i = 0; i < 500; ++i) ids[i] = i;
        const NearestNode tree(dim, p, ids);
        const std::vector<double> q = nearest_test_points(dim, 50, 9);
        for (int j = 0; j < 50; ++j) {
            const double* x = q.data() + j * dim;
            const std::vector<double> exact = nearest_test_distances(dim, p, x);
            std::int64_t index[4];
            double distance[4];
            ASSERT_EQ(tree.nearest_k(x, 4, index, distance), 4u);
            for (int k = 0; k < 4; ++k) {
                EXPECT_DOUBLE_EQ(distance[k], exact[k]) << j << " " << k;
                double s = 0;
                for (int d = 0; d < dim; ++d) s += std::pow(p[index[k] * dim + d] - x[d], 2);
                EXPECT_DOUBLE_EQ(distance[k], std::sqrt(s));
            }
            EXPECT_EQ(index[0], tree.nearest(x).index);
            // Approximate: each within the bound, still nearest first.
            ASSERT_EQ(tree.nearest_k(x, 4, index, distance, 0.5), 4u);
            EXPECT_LE(distance[0], std::sqrt(1.5) * exact[0] * (1 + 1e-12));
            EXPECT_TRUE(std::is_sorted(distance, distance + 4));
        }
        // Fewer nodes than asked for.
        const NearestNode small(dim, p, std::vector<NodeId>{0, 1});
        std::int64_t index[4];
        double distance[4];
        EXPECT_EQ(small.nearest_k(q.data(), 4, index, distance), 2u);
        EXPECT_EQ(NearestNode(dim, p, {}).nearest_k(q.data(), 4, index, distance), 0u);
    }
}

TEST(NearestNode, SpacingIsTheDistanceToTheNearestOtherPositionEvenWithTwins) {
    // Points 0 and 1 coincide; 2 is 0.5 away, 3 is 2 away.
    const std::vector<double> p = {0, 0, 0, 0, 0.5, 0, 2, 0};
    const NearestNode tree(2, p, std::vector<NodeId>{0, 1, 2, 3});
    EXPECT_DOUBLE_EQ(tree.spacing(0), 0.5);
    EXPECT_DOUBLE_EQ(tree.spacing(1), 0.5);
    EXPECT_DOUBLE_EQ(tree.spacing(2), 0.5);
    EXPECT_DOUBLE_EQ(tree.spacing(3), 1.5);
}
