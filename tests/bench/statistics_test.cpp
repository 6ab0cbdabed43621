// The benchmark's order statistics against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/bench/statistics.hpp"

using namespace dgwarp;

TEST(Statistics, MedianOfOddAndEvenCountsAndOfNone) {
    EXPECT_EQ(median({3, 1, 2}), 2);
    EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_EQ(median({7}), 7);
    EXPECT_TRUE(std::isnan(median({})));
}

TEST(Statistics, PercentileIsTheNearestRank) {
    const std::vector<double> v = {15, 20, 35, 40, 50};  // the nearest-rank method's textbook example
    EXPECT_EQ(percentile(v, 5), 15);                     // rank ceil(0.25) = 1
    EXPECT_EQ(percentile(v, 30), 20);                    // rank ceil(1.5) = 2
    EXPECT_EQ(percentile(v, 40), 20);                    // rank 2 exactly
    EXPECT_EQ(percentile(v, 50), 35);
    EXPECT_EQ(percentile(v, 100), 50);
    EXPECT_EQ(percentile(v, 0), 15);
    EXPECT_TRUE(std::isnan(percentile({}, 50)));
}
