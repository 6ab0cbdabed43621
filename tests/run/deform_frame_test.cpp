#include "dgwarp/run/deform_frame.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "dgwarp/repair/unrepairable_cells.hpp"
#include "support/small_grid_with_hole.hpp"
#include "support/split_grid.hpp"

using namespace dgwarp;

namespace {

// Node 5 (1, 1) pushed past node 6 (2, 1) and node 10: the cells around it fold.
std::vector<double> with_node_5_at(const Mesh& m, double x, double y) {
    std::vector<double> p = m.points;
    p[10] = x;
    p[11] = y;
    return p;
}

}  // namespace

TEST(DeformFrame, StepOptionsTurnTheGuardOffOnlyWhereTheBoundaryFolds) {
    MethodOptions o;
    o.dg_harmonic.redo_below = 0.4;
    EXPECT_EQ(step_options(o, 0).dg_harmonic.redo_below, 0.4);
    EXPECT_EQ(step_options(o, 3).dg_harmonic.redo_below, -1);
}

TEST(DeformFrame, StepWarningsAreCodedWithTheirCount) {
    EXPECT_TRUE(step_warnings(StepReport{}).empty());
    StepReport r;
    r.conflicting_shared_vertices = 3;
    const std::vector<Warning> w = step_warnings(r);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].code, WarningCode::conflicting_shared_motions);
    EXPECT_EQ(w[0].count, 3);
    EXPECT_EQ(w[0].text.rfind("3 groups of boundary nodes", 0), 0u) << w[0].text;
    ResolvedFrame motion;
    motion.warnings.push_back({WarningCode::large_rotation, "turns"});
    const std::vector<Warning> all = frame_warnings(motion, r);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].code, WarningCode::large_rotation);  // the motion's first
    EXPECT_EQ(all[1].code, WarningCode::conflicting_shared_motions);
}

TEST(DeformFrame, WorstCellsAreTheLowestQualityFirstStable) {
    const std::vector<double> q = {0.5, -0.1, 0.2, -0.1, -0.3};
    EXPECT_EQ(worst_cells({0, 1, 2, 3, 4}, q, 3), (std::vector<std::int64_t>{4, 1, 3}));
    EXPECT_EQ(worst_cells({2, 0}, q, 10), (std::vector<std::int64_t>{2, 0}));
    EXPECT_TRUE(worst_cells({}, q, 10).empty());
}

TEST(DeformFrame, MeasureFrameAgainstHandComputedCells) {
    const test::SplitGrid g = test::split_grid();
    const OriginalCells original = measure_original(g.mesh);
    // Unmoved: every ratio 1, nothing inverted.
    FrameCells same = measure_frame(g.mesh, g.mesh.points, original, g.ring);
    EXPECT_EQ(same.quality, original.quality);
    for (double r : quality_ratios(same.quality, original.quality)) EXPECT_DOUBLE_EQ(r, 1);
    EXPECT_TRUE(same.inverted.empty());
    // Node 5 beyond node 6: the cells that hold node 5 and lie on its right fold, found by brute force.
    const std::vector<double> moved = with_node_5_at(g.mesh, 2.5, 1);
    const FrameCells c = measure_frame(g.mesh, moved, original, g.ring);
    const std::vector<double> q = cell_qualities(g.mesh, moved, original.orientation);
    EXPECT_EQ(c.quality, q);
    std::vector<std::int64_t> folded;
    for (std::size_t k = 0; k < q.size(); ++k) {
        if (q[k] <= 0) folded.push_back(static_cast<std::int64_t>(k));
    }
    ASSERT_FALSE(folded.empty());
    EXPECT_EQ(c.inverted, folded);
    EXPECT_TRUE(c.inverted_on_boundary.empty());  // every folded cell holds node 5, a volume node
}

TEST(DeformFrame, DgHarmonicsLastResortRepairsWhatItsStepFolded) {
    const test::SplitGrid g = test::split_grid();
    const OriginalCells original = measure_original(g.mesh);
    std::vector<double> points = with_node_5_at(g.mesh, 2.5, 1);
    FrameReport report;
    const FrameCells cells = finish_frame(Method::dg_harmonic, g.mesh, original, g.ring, {}, points, report);
    ASSERT_TRUE(report.untangled.has_value());
    EXPECT_TRUE(report.last_resort);
    EXPECT_GT(report.untangled->inverted_before, 0);
    EXPECT_EQ(report.inverted_by_motion, 0);
    EXPECT_TRUE(report.valid());
    EXPECT_TRUE(cells.inverted.empty());
    EXPECT_EQ(report.quality.inverted, 0);
    EXPECT_EQ(cells.quality, cell_qualities(g.mesh, points, original.orientation));  // measured after the repair
    // The boundary nodes did not move.
    for (NodeId n : g.ring)
        for (int d = 0; d < 2; ++d)
            EXPECT_EQ(points[static_cast<std::size_t>(2 * n + d)], g.mesh.points[static_cast<std::size_t>(2 * n + d)]);
}

TEST(DeformFrame, NoRepairUnlessTheMethodOrTheOptionsAskForIt) {
    const test::SplitGrid g = test::split_grid();
    const OriginalCells original = measure_original(g.mesh);
    const std::vector<double> folded_points = with_node_5_at(g.mesh, 2.5, 1);
    for (const auto& [method, repair] : {std::pair{Method::dg_idw, Repair::method_default},
                                         std::pair{Method::dg_harmonic, Repair::none}}) {
        std::vector<double> points = folded_points;
        FrameOptions options;
        options.repair = repair;
        options.worst_count = 2;
        FrameReport report;
        const FrameCells cells = finish_frame(method, g.mesh, original, g.ring, options, points, report);
        EXPECT_EQ(points, folded_points);
        EXPECT_FALSE(report.untangled.has_value());
        EXPECT_FALSE(report.valid());
        EXPECT_EQ(report.inverted_by_motion, static_cast<std::int64_t>(cells.inverted.size()));
        EXPECT_EQ(report.worst_inverted, worst_cells(cells.inverted, cells.quality, 2));
        EXPECT_EQ(report.quality.inverted, report.inverted_by_motion);
    }
    // Repair::untangle for any method.
    std::vector<double> points = folded_points;
    FrameOptions options;
    options.repair = Repair::untangle;
    FrameReport report;
    finish_frame(Method::idw, g.mesh, original, g.ring, options, points, report);
    ASSERT_TRUE(report.untangled.has_value());
    EXPECT_FALSE(report.last_resort);
    EXPECT_TRUE(report.valid());
}

TEST(DeformFrame, CellsTheBoundaryMotionFoldsAreNamedAndNotRepaired) {
    // The ring's corner cell 0 (nodes 0, 1, 5): node 1 on the boundary moved across, with 5 fixed too.
    test::SplitGrid g = test::split_grid();
    const OriginalCells original = measure_original(g.mesh);
    std::vector<NodeId> fixed = g.ring;
    fixed.push_back(5);
    std::sort(fixed.begin(), fixed.end());
    std::vector<double> points = g.mesh.points;
    points[3] = 2.5;  // node 1 (1, 0) -> (1, 2.5)
    const std::vector<double> before = points;
    FrameReport report;
    const FrameCells cells = finish_frame(Method::dg_harmonic, g.mesh, original, fixed, {}, points, report);
    EXPECT_EQ(cells.inverted_on_boundary, cells_with_only_fixed_nodes(g.mesh.cells, fixed, cells.inverted));
    ASSERT_FALSE(cells.inverted_on_boundary.empty());
    EXPECT_EQ(report.inverted_on_boundary, static_cast<std::int64_t>(cells.inverted_on_boundary.size()));
    EXPECT_FALSE(report.untangled.has_value());  // no volume repair can help: nothing ran
    EXPECT_EQ(points, before);
}

TEST(DeformFrame, DeformFrameIsTheStepThenItsMeasure) {
    const Mesh mesh = test::small_grid_with_hole();
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["rectangle"] = RigidMotion{NodeMotion{{0.3, -0.2, 0}, {0, 0, 0.2}, {0, 0, 0}}};
    spec.frames.push_back(frame);
    const ResolvedBoundary boundary = resolve_boundary(mesh, spec);
    const ResolvedFrame motion = resolve_frame(mesh, spec, boundary, 0);
    const OriginalCells original = measure_original(mesh);
    for (Method method : {Method::dg_idw, Method::dg_harmonic}) {
        const Plan plan = prepare(method, mesh.dim, mesh.points, mesh.cells, boundary.boundary);
        std::vector<double> out(mesh.points.size());
        FrameCells cells;
        const FrameReport r = deform_frame(plan, mesh, original, boundary, motion, {}, {}, out, &cells);
        std::vector<double> expected(mesh.points.size());
        deform(plan, mesh.points, motion.motion, expected);
        EXPECT_EQ(out, expected) << method_name(method);  // valid: no repair moved a node
        EXPECT_EQ(cells.quality, cell_qualities(mesh, expected, original.orientation));
        EXPECT_TRUE(r.valid());
        EXPECT_EQ(r.quality.min, summarize_quality(cells.quality).min);
        EXPECT_GE(r.step_seconds, 0);
    }
}
