#include "dgwarp/repair/last_resort.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "dgwarp/quality/mesh_quality.hpp"
#include "support/split_grid.hpp"

using namespace dgwarp;

using test::SplitGrid;

TEST(LastResort, RepairsCellsAVolumeNodeFoldedAndNothingElse) {
    SplitGrid g = test::split_grid();
    const std::vector<std::int8_t> orient = cell_orientations(g.mesh);
    const std::vector<double> before = cell_qualities(g.mesh, orient);
    // Nothing folded: nothing runs.
    EXPECT_FALSE(run_last_resort(2, g.mesh.cells, orient, g.ring, {}, g.mesh.points));
    // Interior node 5 (1, 1) pushed past node 6 (2, 1): cells fold; it has neighbours to go back between.
    Mesh moved = g.mesh;
    moved.points[2 * 5] = 2.6;
    const std::vector<std::int64_t> folded = newly_inverted_cells(cell_qualities(moved, orient), before);
    ASSERT_FALSE(folded.empty());
    const auto report = run_last_resort(2, moved.cells, orient, g.ring, folded, moved.points);
    ASSERT_TRUE(report.has_value());
    EXPECT_LE(report->rounds, last_resort_max_rounds);
    EXPECT_EQ(report->inverted_after, 0);
    EXPECT_TRUE(newly_inverted_cells(cell_qualities(moved, orient), before).empty());
}

TEST(LastResort, DoesNotRunWhenTheBoundaryItselfFoldsACell) {
    SplitGrid g = test::split_grid();
    const std::vector<std::int8_t> orient = cell_orientations(g.mesh);
    const std::vector<double> before = cell_qualities(g.mesh, orient);
    // Corner node 12 (0, 3) moved to (2.5, 3): the all-boundary triangle (8, 13, 12) folds.
    Mesh moved = g.mesh;
    moved.points[2 * 12] = 2.5;
    const std::vector<std::int64_t> folded = newly_inverted_cells(cell_qualities(moved, orient), before);
    ASSERT_FALSE(folded.empty());
    const std::vector<double> points = moved.points;
    EXPECT_FALSE(run_last_resort(2, moved.cells, orient, g.ring, folded, moved.points));
    EXPECT_EQ(moved.points, points);  // untouched
}
