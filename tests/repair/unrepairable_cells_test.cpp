#include "dgwarp/repair/unrepairable_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

namespace {

// A 3 × 3 grid of unit squares, each split into two triangles (16 nodes,
// node (i, j) = 4 j + i); the boundary is the outer ring of 12 nodes.
ElementList split_grid_cells() {
    ElementList cells;
    for (NodeId j = 0; j < 3; ++j)
        for (NodeId i = 0; i < 3; ++i) {
            const NodeId a = 4 * j + i, b = a + 1, c = a + 5, d = a + 4;
            const NodeId t1[] = {a, b, c}, t2[] = {a, c, d};
            cells.push_back(CellType::triangle, t1);
            cells.push_back(CellType::triangle, t2);
        }
    return cells;
}

std::vector<NodeId> grid_ring() {
    std::vector<NodeId> ring;
    for (NodeId n = 0; n < 16; ++n)
        if (n % 4 == 0 || n % 4 == 3 || n / 4 == 0 || n / 4 == 3) ring.push_back(n);
    return ring;
}

}  // namespace

TEST(UnrepairableCells, AreTheCandidatesWhoseNodesAreAllFixedComparedByBruteForce) {
    const ElementList cells = split_grid_cells();
    const std::vector<NodeId> ring = grid_ring();
    ASSERT_EQ(ring.size(), 12u);
    std::vector<std::int64_t> all(cells.size());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = static_cast<std::int64_t>(c);
    const std::vector<std::int64_t> found = cells_with_only_fixed_nodes(cells, ring, all);
    // Brute force: the triangles without an interior node (5, 6, 9, 10).
    std::vector<std::int64_t> expected;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        if (std::none_of(nodes.begin(), nodes.end(), [](NodeId n) { return n == 5 || n == 6 || n == 9 || n == 10; }))
            expected.push_back(static_cast<std::int64_t>(c));
    }
    EXPECT_EQ(found, expected);
    // By hand: only two triangles miss every interior node, (2, 3, 7) and (8, 13, 12).
    EXPECT_EQ(expected, (std::vector<std::int64_t>{4, 13}));
    // Only the given candidates are looked at, in their order.
    const std::int64_t some[] = {expected[1], 0, expected[0]};
    EXPECT_EQ(cells_with_only_fixed_nodes(cells, ring, some), (std::vector<std::int64_t>{expected[1], expected[0]}));
    EXPECT_TRUE(cells_with_only_fixed_nodes(cells, {}, all).empty());
}

TEST(UnrepairableCells, ACandidateOutOfRangeIsAMeshError) {
    const ElementList cells = split_grid_cells();
    const std::int64_t bad[] = {18};
    EXPECT_THROW(cells_with_only_fixed_nodes(cells, grid_ring(), bad), MeshError);
}
