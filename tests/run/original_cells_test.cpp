#include "dgwarp/run/original_cells.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

namespace {

// Three counter-clockwise triangles and one written clockwise (cell 3).
Mesh strip_with_a_flipped_cell() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
    const NodeId t0[] = {0, 1, 4}, t1[] = {0, 4, 3}, t2[] = {1, 2, 5}, t3[] = {1, 4, 5};
    for (const auto* t : {t0, t1, t2, t3}) m.cells.push_back(CellType::triangle, std::span<const NodeId>(t, 3));
    return m;
}

}  // namespace

TEST(OriginalCells, JudgesEveryCellByItsTypesMajority) {
    const Mesh m = strip_with_a_flipped_cell();
    const OriginalCells o = measure_original(m);
    EXPECT_EQ(o.own_orientation, (std::vector<std::int8_t>{1, 1, 1, -1}));
    EXPECT_EQ(o.orientation, (std::vector<std::int8_t>{1, 1, 1, 1}));
    // What the quality driver gives with those orientations, cell by cell.
    EXPECT_EQ(o.quality, cell_qualities(m, o.orientation));
    EXPECT_GT(o.quality[0], 0);
    EXPECT_LE(o.quality[3], 0);  // flipped against the majority: inverted before any motion
    EXPECT_EQ(o.summary.inverted, 1);
    EXPECT_EQ(o.summary.worst_cell, 3);
    EXPECT_EQ(o.summary.cells, 4);
}

TEST(OriginalCells, GivenOrientationsAreUsedAndChecked) {
    const Mesh m = strip_with_a_flipped_cell();
    // A decomposed mesh's vote may differ from this part's: cell 3 judged as written.
    const OriginalCells o = measure_original(m, cell_orientations(m), {1, 1, 1, -1});
    EXPECT_EQ(o.summary.inverted, 0);
    EXPECT_GT(o.quality[3], 0);
    EXPECT_THROW(measure_original(m, cell_orientations(m), {1, 1, 1}), MeshError);
    EXPECT_THROW(measure_original(m, {1}, {1, 1, 1, 1}), MeshError);
}
