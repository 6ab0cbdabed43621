// untangle: moves volume nodes around inverted cells until none is inverted.
// Properties checked on structured meshes with nodes pushed through their
// neighbours (quadrilaterals, tetrahedra, hexahedra): every inverted cell is
// repaired, fixed nodes and nodes far from the damage keep every bit, the
// report counts what the quality driver counts, the result does not depend on
// the thread count, and what cannot be repaired (a cell whose nodes are all
// fixed) is reported, not hidden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "dgwarp/cases/grid_with_hole.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/repair/untangle.hpp"

using namespace dgwarp;

namespace {

/// The cube [0, 1]³ as n³ hexahedra (VTK order), or each hexahedron cut into
/// six tetrahedra around its main diagonal (Kuhn), all positively oriented.
Mesh cube_grid(int n, bool tetrahedra) {
    Mesh m;
    m.dim = 3;
    auto id = [n](int i, int j, int k) { return static_cast<NodeId>((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                for (int c : {i, j, k}) m.points.push_back(double(c) / n);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const NodeId v[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                     id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                     id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                if (!tetrahedra) {
                    m.cells.push_back(CellType::hexahedron, v);
                    continue;
                }
                // Paths from corner 0 to corner 6 along the edges, one tetrahedron each.
                const int paths[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
                for (const auto& p : paths) {
                    NodeId t[4] = {v[0], v[p[0]], v[p[1]], v[6]};
                    m.cells.push_back(CellType::tetrahedron, t);
                }
            }
    // Give every tetrahedron a positive orientation (the paths alternate).
    if (tetrahedra) {
        const auto orientation = cell_orientations(m);
        for (std::size_t c = 0; c < m.cells.size(); ++c)
            if (orientation[c] < 0) std::swap(m.cells.nodes[m.cells.offsets[c] + 1], m.cells.nodes[m.cells.offsets[c] + 2]);
    }
    return m;
}

/// The nodes on the cube's faces.
std::vector<NodeId> cube_faces(const Mesh& m) {
    std::vector<NodeId> out;
    for (std::size_t i = 0; i < m.num_points(); ++i) {
        bool face = false;
        for (int d = 0; d < 3; ++d) face |= m.points[3 * i + d] == 0.0 || m.points[3 * i + d] == 1.0;
        if (face) out.push_back(static_cast<NodeId>(i));
    }
    return out;
}

std::vector<NodeId> marker_nodes_of(const Mesh& m) {
    std::vector<NodeId> out;
    for (const Marker& marker : m.markers)
        for (NodeId n : marker_nodes(marker)) out.push_back(n);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

QualitySummary judge(const Mesh& reference, const std::vector<double>& points) {
    Mesh moved = reference;
    moved.points = points;
    return summarize_quality(cell_qualities(moved, cell_orientations(reference)));
}

/// Pushes every node in `nodes` by up to `amount` in each coordinate (seeded).
void shake(std::vector<double>& points, int dim, const std::vector<NodeId>& nodes, double amount, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    for (NodeId n : nodes)
        for (int d = 0; d < dim; ++d) points[static_cast<std::size_t>(n) * dim + d] += u(rng);
}

std::vector<NodeId> complement(std::size_t num_points, const std::vector<NodeId>& fixed) {
    std::vector<NodeId> out;
    for (std::size_t i = 0; i < num_points; ++i)
        if (!std::binary_search(fixed.begin(), fixed.end(), static_cast<NodeId>(i))) out.push_back(static_cast<NodeId>(i));
    return out;
}

/// Runs untangle on `points` (damaged) with `fixed` held, checks it repaired
/// every inverted cell without moving a fixed node, and returns the report
/// and the quality after.
std::pair<UntangleReport, QualitySummary> repair_and_check(const Mesh& mesh, const std::vector<NodeId>& fixed,
                                                           std::vector<double>& points) {
    const QualitySummary damaged = judge(mesh, points);
    EXPECT_GT(damaged.inverted, 0);
    const std::vector<double> before = points;
    const UntangleReport r = untangle(mesh.dim, mesh.cells, cell_orientations(mesh), fixed, points);
    const QualitySummary repaired = judge(mesh, points);
    EXPECT_EQ(r.inverted_before, damaged.inverted);
    EXPECT_EQ(r.inverted_after, 0);
    EXPECT_EQ(repaired.inverted, 0);
    EXPECT_GT(r.min_quality_after, 0);
    EXPECT_GE(r.min_quality_after, repaired.min);  // the worst of the cells it changed
    for (NodeId n : fixed)
        for (int d = 0; d < mesh.dim; ++d) {
            const std::size_t k = static_cast<std::size_t>(n) * mesh.dim + d;
            EXPECT_EQ(points[k], before[k]) << "fixed node " << n;
        }
    return {r, repaired};
}

}  // namespace

TEST(Untangle, AValidMeshIsLeftAsItIs) {
    const Mesh mesh = cube_grid(4, true);
    std::vector<double> points = mesh.points;
    shake(points, 3, complement(mesh.num_points(), cube_faces(mesh)), 0.02, 1);  // small: nothing inverts
    const std::vector<double> before = points;
    const UntangleReport r =
        untangle(3, mesh.cells, cell_orientations(mesh), cube_faces(mesh), points);
    EXPECT_EQ(r.inverted_before, 0);
    EXPECT_EQ(r.inverted_after, 0);
    EXPECT_EQ(r.nodes_moved, 0);
    EXPECT_EQ(r.rounds, 0);
    EXPECT_EQ(points, before);
}

TEST(Untangle, ANodePushedThroughItsNeighbourIsPulledBackIn2DQuadrilaterals) {
    const Mesh mesh = make_grid_with_hole();  // 49 cells a side, hole 21 × 9
    const std::vector<NodeId> fixed = marker_nodes_of(mesh);
    std::vector<double> points = mesh.points;
    // Node (5, 5) of the grid pushed 1.6 cells right, past node (6, 5).
    const double h = 20.0 / 49;
    NodeId pushed = -1;
    for (std::size_t i = 0; i < mesh.num_points(); ++i)
        if (std::abs(mesh.points[2 * i] - (-10 + 5 * h)) < 1e-9 && std::abs(mesh.points[2 * i + 1] - (-10 + 5 * h)) < 1e-9)
            pushed = static_cast<NodeId>(i);
    ASSERT_GE(pushed, 0);
    points[2 * static_cast<std::size_t>(pushed)] += 1.6 * h;
    const std::vector<double> before = points;

    const auto [r, repaired] = repair_and_check(mesh, fixed, points);
    EXPECT_GT(repaired.min, 0.2);
    EXPECT_GT(r.nodes_moved, 0);
    // Nodes more than 12 cells from the push were never touched.
    for (std::size_t i = 0; i < mesh.num_points(); ++i) {
        const double dist = std::hypot(mesh.points[2 * i] - mesh.points[2 * static_cast<std::size_t>(pushed)],
                                       mesh.points[2 * i + 1] - mesh.points[2 * static_cast<std::size_t>(pushed) + 1]);
        if (dist > 12 * h) {
            EXPECT_EQ(points[2 * i], before[2 * i]) << "node " << i;
            EXPECT_EQ(points[2 * i + 1], before[2 * i + 1]) << "node " << i;
        }
    }
    // The report's largest move is the largest move.
    double largest = 0;
    for (std::size_t i = 0; i < mesh.num_points(); ++i)
        largest = std::max(largest, std::hypot(points[2 * i] - before[2 * i], points[2 * i + 1] - before[2 * i + 1]));
    EXPECT_DOUBLE_EQ(r.max_move, largest);
}

TEST(Untangle, ShakenTetrahedraAndHexahedraAreAllRepaired) {
    for (const bool tetrahedra : {true, false}) {
        SCOPED_TRACE(tetrahedra ? "tetrahedra" : "hexahedra");
        const Mesh mesh = cube_grid(8, tetrahedra);
        const std::vector<NodeId> fixed = cube_faces(mesh);
        std::vector<double> points = mesh.points;
        shake(points, 3, complement(mesh.num_points(), fixed), 0.6 / 8, 7);  // up to 0.6 cells: many cells invert
        ASSERT_GT(judge(mesh, points).inverted, 10);
        const auto [r, repaired] = repair_and_check(mesh, fixed, points);
        EXPECT_GT(r.rounds, 0);
    }
}

TEST(Untangle, ATargetQualityAlsoLiftsThePoorCells) {
    const Mesh mesh = cube_grid(6, true);
    const std::vector<NodeId> fixed = cube_faces(mesh);
    std::vector<double> points = mesh.points;
    shake(points, 3, complement(mesh.num_points(), fixed), 0.45 / 6, 3);
    std::vector<double> only_untangled = points;
    UntangleOptions options;
    options.target_quality = 0.2;
    const UntangleReport r = untangle(3, mesh.cells, cell_orientations(mesh), fixed, points, options);
    untangle(3, mesh.cells, cell_orientations(mesh), fixed, only_untangled);
    EXPECT_GT(r.below_target_before, r.inverted_before);
    EXPECT_EQ(r.below_target_after, 0);
    EXPECT_GT(judge(mesh, points).min, 0.2);
    EXPECT_GT(judge(mesh, points).min, judge(mesh, only_untangled).min);
}

TEST(Untangle, TheResultDoesNotDependOnTheThreadCount) {
    const Mesh mesh = cube_grid(8, true);
    const std::vector<NodeId> fixed = cube_faces(mesh);
    std::vector<double> damaged = mesh.points;
    shake(damaged, 3, complement(mesh.num_points(), fixed), 0.6 / 8, 11);
    std::vector<std::vector<double>> results;
    const int threads = num_threads();
    for (int t : {1, 2}) {
        set_num_threads(t);
        std::vector<double> points = damaged;
        untangle(3, mesh.cells, cell_orientations(mesh), fixed, points);
        results.push_back(points);
    }
    set_num_threads(threads);
    EXPECT_EQ(results[0], results[1]);
}

TEST(Untangle, ACellWhoseNodesAreAllFixedIsReportedNotRepaired) {
    Mesh mesh;
    mesh.dim = 3;
    mesh.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const NodeId t[4] = {0, 1, 2, 3};
    mesh.cells.push_back(CellType::tetrahedron, t);
    std::vector<double> points = mesh.points;
    points[11] = -1;  // the apex through the base
    const std::vector<double> before = points;
    const UntangleReport r = untangle(3, mesh.cells, cell_orientations(mesh), std::vector<NodeId>{0, 1, 2, 3}, points);
    EXPECT_EQ(r.inverted_before, 1);
    EXPECT_EQ(r.inverted_after, 1);
    EXPECT_EQ(r.nodes_moved, 0);
    EXPECT_EQ(points, before);
    // With the apex free it is repaired.
    const UntangleReport free_apex = untangle(3, mesh.cells, cell_orientations(mesh), std::vector<NodeId>{0, 1, 2}, points);
    EXPECT_EQ(free_apex.inverted_after, 0);
    EXPECT_GT(points[11], 0);
}

TEST(Untangle, BadInputThrowsNamingWhatIsWrong) {
    const Mesh mesh = cube_grid(2, true);
    std::vector<double> points = mesh.points;
    const auto orientation = cell_orientations(mesh);
    const std::vector<NodeId> none;
    EXPECT_THROW(untangle(4, mesh.cells, orientation, none, points), MeshError);
    EXPECT_THROW(untangle(3, mesh.cells, std::span(orientation).first(3), none, points), MeshError);
    EXPECT_THROW(untangle(3, mesh.cells, orientation, none, std::span(points).first(points.size() - 1)), MeshError);
    EXPECT_THROW(untangle(3, mesh.cells, orientation, std::vector<NodeId>{1000}, points), MeshError);
    ElementList bad = mesh.cells;
    bad.nodes[0] = 1000;
    EXPECT_THROW(untangle(3, bad, orientation, none, points), MeshError);
    UntangleOptions options;
    options.target_quality = 1.0;
    EXPECT_THROW(untangle(3, mesh.cells, orientation, none, points, options), Error);
    options.target_quality = -0.1;
    EXPECT_THROW(untangle(3, mesh.cells, orientation, none, points, options), Error);
}

// The paper's twisted bar after the twist and a 45° rotation: DG-IDW with the
// paper's weights inverts cells in bands along the Delaunay graph's edges
// (docs/RESULTS-DISCUSSION.md); no single node can leave such a band, and the
// rounds' smoothing restart is what unfolds it (measured: 151 inverted -> 0).
TEST(Untangle, UnfoldsTheTwistedBarAfterTheTwistAndTheRotation) {
    const Mesh mesh = make_case("twisted-bar");
    const auto motions = case_motions("twisted-bar", mesh);
    const CaseMotion& cm = motions.at(1);
    ASSERT_EQ(cm.name, "twist-rotate-45");
    const ResolvedBoundary b = resolve_boundary(mesh, cm.spec);
    const BoundaryMotion motion = resolve_frame(mesh, cm.spec, b, 0).motion;
    const Plan plan = prepare(Method::dg_idw, 2, mesh.points, b.boundary);
    std::vector<double> points(mesh.points.size());
    deform(plan, mesh.points, motion, points);
    ASSERT_NEAR(double(judge(mesh, points).inverted), 151.0, 8.0);  // measured 151
    repair_and_check(mesh, b.boundary.nodes, points);
}

TEST(Untangle, CellsToUntangleAreTheInvertedOnesWithAFreeNodeOrThoseBelowTheTarget) {
    // Two tetrahedra on the base 0-1-2: apex 3 above it, apex 4 below it (orientations from the original).
    Mesh mesh;
    mesh.dim = 3;
    mesh.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1};
    const NodeId up[4] = {0, 1, 2, 3}, down[4] = {0, 2, 1, 4};
    mesh.cells.push_back(CellType::tetrahedron, up);
    mesh.cells.push_back(CellType::tetrahedron, down);
    const std::vector<std::int8_t> orientation = cell_orientations(mesh);
    std::vector<double> points = mesh.points;
    points[11] = -0.5;  // apex 3 through the base: the first cell inverts
    EXPECT_EQ(cells_to_untangle(3, mesh.cells, orientation, std::vector<NodeId>{0, 1, 2}, points),
              std::vector<std::int64_t>{0});
    // Every node of it fixed: nothing untangle could move.
    EXPECT_TRUE(cells_to_untangle(3, mesh.cells, orientation, std::vector<NodeId>{0, 1, 2, 3}, points).empty());
    // A target above the second cell's quality takes it too; what untangle then starts from.
    points[11] = 1;
    points[14] = -0.05;  // a flat second cell
    UntangleOptions lift;
    lift.target_quality = 0.5;
    const std::vector<std::int64_t> poor = cells_to_untangle(3, mesh.cells, orientation, std::vector<NodeId>{0, 1, 2}, points, lift);
    EXPECT_EQ(poor, std::vector<std::int64_t>{1});
    std::vector<double> repaired = points;
    EXPECT_EQ(untangle(3, mesh.cells, orientation, std::vector<NodeId>{0, 1, 2}, repaired, lift).below_target_before,
              static_cast<std::int64_t>(poor.size()));
}

TEST(Untangle, GivenCellsAreRepairedAndOthersAtOrBelowTheTargetLeftAsTheyAre) {
    // Two nodes of the grid pushed through their neighbours, far apart: asked to repair the first's cells,
    // untangle leaves the second's (and every node near it) as they are, and counts both.
    const Mesh mesh = make_grid_with_hole();  // 49 cells a side, hole 21 × 9
    const std::vector<NodeId> fixed = marker_nodes_of(mesh);
    const double h = 20.0 / 49;
    const auto node_at = [&](int i, int j) {
        for (std::size_t n = 0; n < mesh.num_points(); ++n)
            if (std::abs(mesh.points[2 * n] - (-10 + i * h)) < 1e-9 && std::abs(mesh.points[2 * n + 1] - (-10 + j * h)) < 1e-9)
                return static_cast<NodeId>(n);
        return NodeId{-1};
    };
    const NodeId first = node_at(5, 5), second = node_at(43, 43);
    ASSERT_GE(first, 0);
    ASSERT_GE(second, 0);
    std::vector<double> points = mesh.points;
    points[2 * static_cast<std::size_t>(first)] += 1.6 * h;
    points[2 * static_cast<std::size_t>(second)] += 1.6 * h;
    const std::vector<std::int8_t> orientation = cell_orientations(mesh);
    const std::vector<std::int64_t> all = cells_to_untangle(2, mesh.cells, orientation, fixed, points);
    std::vector<std::int64_t> near_first;
    for (std::int64_t c : all) {
        const auto nodes = mesh.cells.nodes_of(static_cast<std::size_t>(c));
        if (std::find(nodes.begin(), nodes.end(), first) != nodes.end()) near_first.push_back(c);
    }
    ASSERT_FALSE(near_first.empty());
    ASSERT_LT(near_first.size(), all.size());
    UntangleOptions only;
    only.cells = near_first;
    EXPECT_EQ(cells_to_untangle(2, mesh.cells, orientation, fixed, points, only), near_first);
    const std::vector<double> before = points;
    const UntangleReport r = untangle(2, mesh.cells, orientation, fixed, points, only);
    EXPECT_EQ(r.inverted_before, static_cast<std::int64_t>(all.size()));
    EXPECT_EQ(r.inverted_after, static_cast<std::int64_t>(all.size() - near_first.size()));
    // Nothing within 12 cells of the second node moved.
    for (std::size_t n = 0; n < mesh.num_points(); ++n)
        if (std::hypot(mesh.points[2 * n] - mesh.points[2 * static_cast<std::size_t>(second)],
                       mesh.points[2 * n + 1] - mesh.points[2 * static_cast<std::size_t>(second)]) < 12 * h) {
            EXPECT_EQ(points[2 * n], before[2 * n]) << "node " << n;
            EXPECT_EQ(points[2 * n + 1], before[2 * n + 1]) << "node " << n;
        }
    // A cell out of range is a MeshError.
    const std::int64_t bad[] = {static_cast<std::int64_t>(mesh.cells.size())};
    only.cells = bad;
    EXPECT_THROW(untangle(2, mesh.cells, orientation, fixed, points, only), MeshError);
}
