// Validity of moved graph simplices: exact orientation, with the round-off
// sliver exemption (suite named Dgm*: DGM is its user).
#include "dgwarp/graph/simplex_orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dgwarp;

TEST(DgmGraphValidity, FlagsInvertedAndFlattenedTrianglesButNotValidOnes) {
    const std::vector<std::int32_t> tri = {0, 1, 2};
    const std::vector<double> from = {0, 0, 1, 0, 0, 1};
    // Still positive (even very thin), mirrored, collapsed onto a line.
    const std::vector<double> thin = {0, 0, 1, 0, 0.5, 1e-9};
    const std::vector<double> mirrored = {0, 0, 1, 0, 0, -1};
    const std::vector<double> collinear = {0, 0, 1, 0, 2, 0};
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, from), 0);
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, thin), 0);
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, mirrored), 1);
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, collinear), 1);
}

TEST(DgmGraphValidity, ATriangleFlatToRoundOffBeforeAndAfterIsNotCounted) {
    const std::vector<std::int32_t> tri = {0, 1, 2};
    // Three points on the line y = x / 3 rounded: exact-arithmetic collinear,
    // a sliver whose sign is round-off. 0.1 / 3 and 0.2 / 3 are rounded.
    const std::vector<double> from = {0, 0, 0.1, 0.1 / 3, 0.2, 0.2 / 3};
    const std::vector<double> swapped = {0, 0, 0.2, 0.2 / 3, 0.1, 0.1 / 3};
    // Same sliver moved along the line (still flat): not counted.
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, swapped), 0);
    // The sliver opened into a clearly inverted triangle: counted.
    const std::vector<double> opened = {0, 0, 0.1, 0.1 / 3, 0.2, -0.5};
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, from, opened), 1);
    // A healthy triangle squashed onto the sliver: counted (this also shows
    // that `swapped` is not positively oriented, so the first check above
    // exercised the exemption).
    const std::vector<double> healthy = {0, 0, 1, 0, 0, 1};
    EXPECT_EQ(count_invalid_moved_simplices(2, tri, healthy, swapped), 1);
}

TEST(DgmGraphValidity, TetrahedraAreJudgedTheSameWay) {
    const std::vector<std::int32_t> tets = {0, 1, 2, 3, 1, 0, 2, 4};  // positive at `from`
    const std::vector<double> from = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.3, 0.3, -1};
    EXPECT_EQ(count_invalid_moved_simplices(3, tets, from, from), 0);
    std::vector<double> to = from;
    to[11] = -1;  // vertex 3 through the base plane: the first tetrahedron inverts
    EXPECT_EQ(invalid_moved_simplices(3, tets, from, to), (std::vector<std::uint8_t>{1, 0}));
    to[11] = 0;  // onto the base plane: flat, counted
    EXPECT_EQ(count_invalid_moved_simplices(3, tets, from, to), 1);
}
