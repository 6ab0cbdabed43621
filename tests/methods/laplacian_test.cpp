#include "dgwarp/methods/laplacian.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

// A structured grid of [0,1]^dim with n cells a side, interior nodes jittered
// by up to `jitter` cell sizes; cells: 2D quadrilaterals (or each split into
// two triangles), 3D hexahedra (or each split into two prisms, or with
// `mixed`: prism pairs in every other column of hexahedra). Every node on the
// outer faces is a boundary node, all moving.
struct GridCase {
    Mesh mesh;
    BoundarySet boundary;
};

enum class GridCells { quads, triangles, hexahedra, prisms, mixed };

GridCase laplacian_grid(int dim, int n, GridCells kind, double jitter, unsigned seed = 1) {
    GridCase g;
    g.mesh.dim = dim;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-jitter / n, jitter / n);
    const int nz = dim == 3 ? n : 0;
    const auto id = [&](int i, int j, int k) { return static_cast<NodeId>((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const int c[3] = {i, j, k};
                bool outer = false;
                for (int d = 0; d < dim; ++d) outer |= c[d] == 0 || c[d] == n;
                for (int d = 0; d < dim; ++d) g.mesh.points.push_back(double(c[d]) / n + (outer ? 0.0 : u(rng)));
                if (outer) {
                    g.boundary.nodes.push_back(id(i, j, k));
                    g.boundary.moving.push_back(1);
                }
            }
    for (int k = 0; k < std::max(nz, 1); ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if (dim == 2) {
                    const NodeId q[4] = {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)};
                    if (kind == GridCells::triangles) {
                        g.mesh.cells.push_back(CellType::triangle, std::array<NodeId, 3>{q[0], q[1], q[2]});
                        g.mesh.cells.push_back(CellType::triangle, std::array<NodeId, 3>{q[0], q[2], q[3]});
                    } else {
                        g.mesh.cells.push_back(CellType::quadrilateral, q);
                    }
                    continue;
                }
                const NodeId h[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                     id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                     id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                // mixed: prism pairs in every other x column (conforming: their triangles
                // meet only each other, their quadrilaterals the hexahedra's faces).
                const bool prisms = kind == GridCells::prisms || (kind == GridCells::mixed && i % 2 == 0);
                if (prisms) {
                    g.mesh.cells.push_back(CellType::prism, std::array<NodeId, 6>{h[0], h[1], h[2], h[4], h[5], h[6]});
                    g.mesh.cells.push_back(CellType::prism, std::array<NodeId, 6>{h[0], h[2], h[3], h[4], h[6], h[7]});
                } else {
                    g.mesh.cells.push_back(CellType::hexahedron, h);
                }
            }
    return g;
}

// Every boundary node translated by the affine field A x + b (rows of A).
BoundaryMotion affine_motion(const GridCase& g, const double (&a)[3][3], const Vec3& b) {
    BoundaryMotion motion(g.boundary.nodes.size());
    const int dim = g.mesh.dim;
    for (std::size_t k = 0; k < motion.size(); ++k) {
        const double* x = g.mesh.points.data() + static_cast<std::size_t>(g.boundary.nodes[k]) * dim;
        for (int r = 0; r < dim; ++r) {
            double v = b[r];
            for (int c = 0; c < dim; ++c) v += a[r][c] * x[c];
            motion[k].translation[r] = v;
        }
    }
    return motion;
}

// The paper's rectangle turned 90° (case rect-box, motion rotate-90).
MotionSpec rect_box_turn_90(const Mesh& mesh) {
    for (const CaseMotion& m : case_motions("rect-box", mesh))
        if (m.name == "rotate-90") return m.spec;
    throw Error("rect-box has no motion rotate-90");
}

std::vector<double> laplacian_step(const GridCase& g, const BoundaryMotion& motion, const LaplacianOptions& o) {
    const LaplacianPlan plan = prepare_laplacian(g.mesh.dim, g.mesh.points, g.mesh.cells, g.boundary, o);
    std::vector<double> out(g.mesh.points.size(), std::nan(""));
    deform_laplacian(plan, g.mesh.points, motion, out);
    return out;
}

}  // namespace

TEST(Laplacian, ConstantStiffnessIsExactOnAffineBoundaryMotions) {
    // Constant stiffness: the P1 Laplacian and P1 elasticity reproduce affine
    // fields on any conforming split, so the interior (and the cell and face
    // centres) follow the affine field exactly; a wrong split (a face centre
    // not shared, a missing face) breaks this.
    const double a[3][3] = {{0.10, -0.05, 0.02}, {0.03, 0.08, -0.04}, {-0.02, 0.05, 0.06}};
    const Vec3 b{0.01, -0.02, 0.03};
    for (auto model : {LaplacianModel::laplacian, LaplacianModel::elasticity})
    for (auto [dim, kind] : {std::pair{2, GridCells::quads}, std::pair{2, GridCells::triangles},
                             std::pair{3, GridCells::hexahedra}, std::pair{3, GridCells::prisms},
                             std::pair{3, GridCells::mixed}}) {
        SCOPED_TRACE(std::to_string(dim) + "D, kind " + std::to_string(int(kind)) + ", model " +
                     std::to_string(int(model)));
        const GridCase g = laplacian_grid(dim, dim == 2 ? 7 : 4, kind, 0.2);
        LaplacianOptions o;
        o.model = model;
        o.stiffness_exponent = 0;
        o.increments = 1;
        const std::vector<double> out = laplacian_step(g, affine_motion(g, a, b), o);
        for (std::size_t n = 0; n < g.mesh.num_points(); ++n)
            for (int r = 0; r < dim; ++r) {
                double expected = g.mesh.points[n * dim + r] + b[r];
                for (int c = 0; c < dim; ++c) expected += a[r][c] * g.mesh.points[n * dim + c];
                ASSERT_NEAR(out[n * dim + r], expected, 1e-12) << "node " << n;
            }
    }
}

TEST(Laplacian, PolyhedraAreSplitConformingly) {
    // snappyHexMesh's sphere in a box (tests/data/openfoam): 272 polyhedra
    // with faces of 3 to 6 nodes beside hexahedra. The split shares each face
    // centre between its two cells (polygons of 5 and 6 nodes too), so an
    // affine motion of every boundary node is reproduced exactly inside.
    GridCase g;
    g.mesh = read_openfoam(test::source_dir() / "tests" / "data" / "openfoam" / "snappy-sphere");
    ASSERT_GT(count_by_type(g.mesh.cells)[static_cast<std::size_t>(CellType::polyhedron)], 0);
    std::vector<NodeId> nodes;
    for (const Marker& m : g.mesh.markers) {
        const std::vector<NodeId> n = marker_nodes(m);
        nodes.insert(nodes.end(), n.begin(), n.end());
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    g.boundary.nodes = nodes;
    g.boundary.moving.assign(nodes.size(), 1);
    const double a[3][3] = {{0.10, -0.05, 0.02}, {0.03, 0.08, -0.04}, {-0.02, 0.05, 0.06}};
    const Vec3 b{0.01, -0.02, 0.03};
    for (auto model : {LaplacianModel::laplacian, LaplacianModel::elasticity}) {
        LaplacianOptions o;
        o.model = model;
        o.stiffness_exponent = 0;
        o.increments = 1;
        const std::vector<double> out = laplacian_step(g, affine_motion(g, a, b), o);
        std::size_t interior = 0;
        for (std::size_t n = 0; n < g.mesh.num_points(); ++n) {
            interior += !std::binary_search(nodes.begin(), nodes.end(), static_cast<NodeId>(n));
            for (int r = 0; r < 3; ++r) {
                double expected = g.mesh.points[n * 3 + r] + b[r];
                for (int c = 0; c < 3; ++c) expected += a[r][c] * g.mesh.points[n * 3 + c];
                ASSERT_NEAR(out[n * 3 + r], expected, 1e-12) << "node " << n << ", model " << int(model);
            }
        }
        EXPECT_GT(interior, 300u);
    }
}

TEST(Laplacian, IncrementsFollowARigidRotationOfTheWholeBoundary) {
    // Each increment's boundary data is affine in the current coordinates, so
    // with constant stiffness every increment is exact: 4 increments of a 100°
    // turn rotate the interior rigidly (a single linear solve would shrink it).
    for (auto model : {LaplacianModel::laplacian, LaplacianModel::elasticity}) {
    const GridCase g = laplacian_grid(2, 8, GridCells::quads, 0.2);
    BoundaryMotion motion(g.boundary.nodes.size());
    for (auto& m : motion) {
        m.rotation = {0, 0, 100 * std::numbers::pi / 180};
        m.center = {0.3, 0.6, 0};
    }
    LaplacianOptions o;
    o.model = model;
    o.stiffness_exponent = 0;
    o.increments = 4;
    const std::vector<double> out = laplacian_step(g, motion, o);
    for (std::size_t n = 0; n < g.mesh.num_points(); ++n) {
        double expected[2];
        apply_motion(motion[0], std::span<const double>(g.mesh.points.data() + 2 * n, 2), expected);
        EXPECT_NEAR(out[2 * n], expected[0], 1e-12);
        EXPECT_NEAR(out[2 * n + 1], expected[1], 1e-12);
    }
    }
}

TEST(Laplacian, StiffenedTranslationIsExactAndZeroMotionIsTheIdentity) {
    for (int dim : {2, 3}) {
        const GridCase g = laplacian_grid(dim, dim == 2 ? 6 : 3, dim == 2 ? GridCells::quads : GridCells::mixed, 0.3);
        BoundaryMotion motion(g.boundary.nodes.size());
        for (auto& m : motion) m.translation = {0.3, -0.2, 0.1};
        const std::vector<double> out = laplacian_step(g, motion, {});
        for (std::size_t k = 0; k < out.size(); ++k)
            EXPECT_NEAR(out[k], g.mesh.points[k] + motion[0].translation[k % dim], 1e-12);
        const std::vector<double> same = laplacian_step(g, BoundaryMotion(g.boundary.nodes.size()), {});
        for (std::size_t k = 0; k < out.size(); ++k) EXPECT_NEAR(same[k], g.mesh.points[k], 1e-14);
    }
}

TEST(Laplacian, ValidOnTheRectangleTurned90WhereOnePassMethodsFold) {
    // The paper's rectangle turned 90°: DGM's moved graph is invalid, DG-IDW
    // with L = auto inverts 4 cells (docs/RESULTS.md); the incremental
    // stiffened elasticity none. The displacement Laplacian shears the cells
    // at the rectangle's corners (and folds them): why elasticity is the default.
    const Mesh mesh = make_case("rect-box");
    const ResolvedBoundary b = resolve_boundary(mesh, rect_box_turn_90(mesh));
    const BoundaryMotion motion = resolve_frame(mesh, rect_box_turn_90(mesh), b, 0).motion;
    const auto orientation = cell_orientations(mesh);
    Mesh out = mesh;
    MethodOptions auto_length;
    auto_length.dg_idw.length_scale = 0;
    deform(prepare(Method::dg_idw, 2, mesh.points, b.boundary, auto_length), mesh.points, motion, out.points);
    EXPECT_GT(summarize_quality(cell_qualities(out, orientation)).inverted, 0);  // the scene folds DG-IDW
    const Plan plan = prepare(Method::laplacian, 2, mesh.points, mesh.cells, b.boundary);
    const StepReport r = deform(plan, mesh.points, motion, out.points);
    EXPECT_EQ(r.substeps, LaplacianOptions{}.increments);  // no fold: no more increments
    const QualitySummary q = summarize_quality(cell_qualities(out, orientation));
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min, 0.1);
    // Boundary nodes exactly where the motion puts them.
    for (std::size_t k = 0; k < b.boundary.nodes.size(); ++k) {
        double x[2];
        const auto n = static_cast<std::size_t>(b.boundary.nodes[k]);
        apply_motion(motion[k], std::span<const double>(mesh.points.data() + 2 * n, 2), x);
        EXPECT_EQ(out.points[2 * n], x[0]);
        EXPECT_EQ(out.points[2 * n + 1], x[1]);
    }
    MethodOptions laplacian;
    laplacian.laplacian.model = LaplacianModel::laplacian;
    laplacian.laplacian.max_increments = laplacian.laplacian.increments;  // no doubling
    deform(prepare(Method::laplacian, 2, mesh.points, mesh.cells, b.boundary, laplacian), mesh.points, motion,
           out.points);
    EXPECT_GT(summarize_quality(cell_qualities(out, orientation)).inverted, 0);
}

TEST(Laplacian, FoldsAskForMoreIncrements) {
    // The plain Laplacian folds the rectangle turned 90° in 4 increments; with
    // doubling allowed, the step is solved again with more, and says so.
    const Mesh mesh = make_case("rect-box");
    const ResolvedBoundary b = resolve_boundary(mesh, rect_box_turn_90(mesh));
    const BoundaryMotion motion = resolve_frame(mesh, rect_box_turn_90(mesh), b, 0).motion;
    MethodOptions o;
    o.laplacian.model = LaplacianModel::laplacian;
    o.laplacian.stiffness_exponent = 1;
    o.laplacian.max_increments = 16;
    Mesh out = mesh;
    const StepReport r = deform(prepare(Method::laplacian, 2, mesh.points, mesh.cells, b.boundary, o), mesh.points,
                                motion, out.points);
    EXPECT_EQ(r.substeps, 16);  // 4, 8, 16: each still folds (the Laplacian shears the corners), the last is kept
    o.laplacian.max_increments = 3;
    EXPECT_THROW(prepare(Method::laplacian, 2, mesh.points, mesh.cells, b.boundary, o), Error);  // below increments
}

TEST(Laplacian, ACappedStepIsThePlanWithThatManyIncrementsAtMost) {
    // deform_laplacian_capped: the same bits as a plan whose max_increments is
    // the cap; a cap above the plan's changes nothing.
    const Mesh mesh = make_case("rect-box");
    const ResolvedBoundary b = resolve_boundary(mesh, rect_box_turn_90(mesh));
    const BoundaryMotion motion = resolve_frame(mesh, rect_box_turn_90(mesh), b, 0).motion;
    LaplacianOptions o;
    o.model = LaplacianModel::laplacian;
    o.stiffness_exponent = 1;
    o.max_increments = 16;
    const LaplacianPlan plan = prepare_laplacian(2, mesh.points, mesh.cells, b.boundary, o);
    for (const auto& [cap, expected] : {std::pair{4, 4}, std::pair{8, 8}, std::pair{64, 16}}) {
        LaplacianOptions capped = o;
        capped.max_increments = std::min(cap, 16);
        std::vector<double> a(mesh.points.size()), c(mesh.points.size());
        EXPECT_EQ(deform_laplacian_capped(plan, mesh.points, motion, a, cap).increments, expected);
        EXPECT_EQ(deform_laplacian(prepare_laplacian(2, mesh.points, mesh.cells, b.boundary, capped), mesh.points,
                                   motion, c)
                      .increments,
                  expected);
        EXPECT_EQ(a, c) << "cap " << cap;
    }
}

TEST(Laplacian, PointsNoCellUsesStayAndOutputMayAliasInput) {
    GridCase g = laplacian_grid(2, 5, GridCells::triangles, 0.2);
    g.mesh.points.insert(g.mesh.points.end(), {0.5, 0.5});  // a stray point (as Gmsh's circle centres)
    BoundaryMotion motion(g.boundary.nodes.size());
    for (auto& m : motion) m.translation = {0.1, 0, 0};
    const LaplacianPlan plan = prepare_laplacian(2, g.mesh.points, g.mesh.cells, g.boundary);
    std::vector<double> x = g.mesh.points;
    deform_laplacian(plan, x, motion, x);  // in place
    EXPECT_EQ(x[x.size() - 2], 0.5);
    EXPECT_EQ(x[x.size() - 1], 0.5);
    EXPECT_NEAR(x[0], g.mesh.points[0] + 0.1, 1e-15);
}

TEST(Laplacian, RefusesBadInputsNamingThem) {
    const GridCase g = laplacian_grid(2, 4, GridCells::quads, 0);
    EXPECT_THROW(prepare(Method::laplacian, 2, g.mesh.points, g.boundary), Error);  // no cells given
    EXPECT_THROW(prepare_laplacian(2, g.mesh.points, ElementList{}, g.boundary), MeshError);
    LaplacianOptions o;
    o.increments = 0;
    EXPECT_THROW(prepare_laplacian(2, g.mesh.points, g.mesh.cells, g.boundary, o), Error);
    o = {};
    o.stiffness_exponent = std::nan("");
    EXPECT_THROW(prepare_laplacian(2, g.mesh.points, g.mesh.cells, g.boundary, o), Error);
    ElementList bad = g.mesh.cells;
    bad.nodes[5] = 1000;
    try {
        prepare_laplacian(2, g.mesh.points, bad, g.boundary);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("node 1000"), std::string::npos) << e.what();
    }
    // A part no boundary node holds (a second grid beside the first, joined
    // to no marker): its displacement is undetermined, refused naming a node.
    GridCase two = laplacian_grid(2, 4, GridCells::triangles, 0);
    const GridCase other = laplacian_grid(2, 4, GridCells::triangles, 0);
    const auto offset = static_cast<NodeId>(two.mesh.num_points());
    for (std::size_t k = 0; k < other.mesh.points.size(); ++k) two.mesh.points.push_back(other.mesh.points[k] + 2.0);
    for (std::size_t c = 0; c < other.mesh.cells.size(); ++c) {
        std::array<NodeId, 3> t;
        for (int k = 0; k < 3; ++k) t[k] = other.mesh.cells.nodes_of(c)[k] + offset;
        two.mesh.cells.push_back(CellType::triangle, t);
    }
    try {
        prepare_laplacian(2, two.mesh.points, two.mesh.cells, two.boundary);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("no boundary node holds"), std::string::npos) << e.what();
        EXPECT_GE(e.index(), offset);
    }
}
