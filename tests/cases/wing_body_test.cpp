#include "dgwarp/cases/wing_body.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

namespace {
// The coarse size, so the tests take seconds; the paper's size is built by `dgwarp bench`.
// Generated once per process: ctest runs the CasesWingBody tests in one (tests/CMakeLists.txt).
const Mesh& coarse() {
    static const Mesh m = make_wing_body(wing_body_size(0));
    return m;
}

std::vector<NodeId> nodes_of(const char* marker) { return marker_nodes(find_marker(coarse(), marker)); }

bool disjoint(const std::vector<NodeId>& a, const std::vector<NodeId>& b) {  // both sorted
    std::vector<NodeId> common;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    return common.empty();
}
}  // namespace

TEST(CasesWingBody, CoarseMeshIsValidPositiveAndDeterministic) {
    const Mesh& m = coarse();
    EXPECT_EQ(m.dim, 3);
    EXPECT_NO_THROW(validate(m));
    EXPECT_GT(m.cells.size(), 10000u);
    EXPECT_EQ(count_by_type(m.cells)[static_cast<int>(CellType::tetrahedron)],
              static_cast<std::int64_t>(m.cells.size()));
    const QualitySummary q = summarize_quality(cell_qualities(m, std::vector<std::int8_t>(m.cells.size(), 1)));
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min, 0.0);
    EXPECT_TRUE(make_wing_body(wing_body_size(0)) == m);
}

TEST(CasesWingBody, MarkersArePresentAndTheFoldingWingSharesNoNode) {
    const Mesh& m = coarse();
    const auto body = nodes_of("body"), wing = nodes_of("wing"), symmetry = nodes_of("symmetry"),
               farfield = nodes_of("farfield");
    EXPECT_GT(body.size(), 100u);
    EXPECT_GT(wing.size(), 100u);
    EXPECT_GT(symmetry.size(), 50u);
    EXPECT_GT(farfield.size(), 50u);
    // The hinge gap (y in [0.87, 0.93]) separates the panel from the stub.
    for (NodeId n : wing) EXPECT_GE(m.points[3 * n + 1], 0.93 - 1e-9);
    for (NodeId n : body) EXPECT_LE(m.points[3 * n + 1], 0.87 + 1e-9);
    for (NodeId n : symmetry) EXPECT_NEAR(m.points[3 * n + 1], 0.0, 1e-9);
    for (NodeId n : farfield) {
        const double x = m.points[3 * n], y = m.points[3 * n + 1], z = m.points[3 * n + 2];
        EXPECT_TRUE(std::abs(x + 25) < 1e-9 || std::abs(x - 30) < 1e-9 || std::abs(y - 25) < 1e-9 ||
                    std::abs(std::abs(z) - 25) < 1e-9)
            << x << " " << y << " " << z;
    }
    EXPECT_TRUE(disjoint(wing, body));
    EXPECT_TRUE(disjoint(wing, symmetry));
    EXPECT_TRUE(disjoint(wing, farfield));
}

TEST(CasesWingBody, FoldTurnsEveryWingNodeTwentyDegreesAboutTheHinge) {
    const Mesh& m = coarse();
    const auto motions = case_motions("wing-body", m);
    ASSERT_EQ(motions.size(), 1u);
    EXPECT_EQ(motions[0].name, "fold-20");
    const ResolvedBoundary b = resolve_boundary(m, motions[0].spec);
    EXPECT_EQ(b.moving_markers, std::vector<std::string>{"wing"});
    EXPECT_TRUE(b.warnings.empty());  // no node on both the wing and a static marker
    const std::vector<double> moved =
        moved_boundary_points(m, b.boundary, resolve_frame(m, motions[0].spec, b, 0).motion);
    // Hand-computed: the hinge is the line along x through (y, z) = (0.9, 0.06 × chord(0.9)),
    // chord(0.9) = 2.2 - 1.3 × 0.9 / 6 = 2.005; a positive turn about +x lifts the tip.
    const double yh = 0.9, zh = 0.06 * 2.005, c = std::cos(std::numbers::pi / 9), s = std::sin(std::numbers::pi / 9);
    std::size_t tip = 0, moving = 0;
    for (std::size_t i = 0; i < b.boundary.nodes.size(); ++i) {
        const NodeId n = b.boundary.nodes[i];
        const double x = m.points[3 * n], y = m.points[3 * n + 1], z = m.points[3 * n + 2];
        if (!b.boundary.moving[i]) {
            for (int k = 0; k < 3; ++k) ASSERT_EQ(moved[3 * i + k], m.points[3 * n + k]);
            continue;
        }
        ++moving;
        EXPECT_NEAR(moved[3 * i], x, 1e-12);
        EXPECT_NEAR(moved[3 * i + 1], yh + c * (y - yh) - s * (z - zh), 1e-12);
        EXPECT_NEAR(moved[3 * i + 2], zh + s * (y - yh) + c * (z - zh), 1e-12);
        if (y > m.points[3 * b.boundary.nodes[tip] + 1]) tip = i;
    }
    EXPECT_EQ(moving, nodes_of("wing").size());
    // The tip (y = 6, on the chord plane within 0.054) rises by about 5.1 sin 20° = 1.74.
    EXPECT_NEAR(moved[3 * tip + 2] - m.points[3 * b.boundary.nodes[tip] + 2], 5.1 * s, 0.06);
}

namespace {
/// The coarse mesh after the fold by `method` (one step), and its quality and the original's.
struct Folded {
    Mesh mesh;
    ResolvedBoundary boundary;
    QualitySummary before, after;
};
Folded fold_with(Method method) {
    const Mesh& m = coarse();
    const CaseMotion fold = case_motions("wing-body", m).front();
    Folded f{m, resolve_boundary(m, fold.spec), {}, {}};
    const BoundaryMotion motion = resolve_frame(m, fold.spec, f.boundary, 0).motion;
    const Plan plan = prepare(method, 3, m.points, f.boundary.boundary);
    deform(plan, m.points, motion, f.mesh.points);
    const auto orientation = cell_orientations(m);
    f.before = summarize_quality(cell_qualities(m, orientation));
    f.after = summarize_quality(cell_qualities(f.mesh, orientation));
    return f;
}
}  // namespace

// The fold itself is feasible on this mesh: global IDW keeps every cell valid.
TEST(CasesWingBody, IdwFoldKeepsEveryCellValid) {
    const Folded f = fold_with(Method::idw);
    EXPECT_EQ(f.after.inverted, 0);
    EXPECT_GT(f.after.min, 0.0);
}

// DG-IDW (the paper's formula, L = 1) puts every boundary node where the fold
// says, but does NOT keep every cell valid: on this coarse mesh one cell of
// 53,679 inverts, above the fuselage (902 of 1.52 M at the paper's size). A
// volume node there lies in a Delaunay-graph simplex with a wing vertex and
// turns with the wing about the hinge ~1 away (moves ~0.1), while its neighbour
// in a simplex without one stays put: the jump is larger than the cells
// (docs/RESULTS-DISCUSSION.md, wing-body). This test bounds the damage; it is
// not a validity check.
TEST(CasesWingBody, DgIdwFoldMovesTheWingExactlyAndInvertsOnlyAFewCells) {
    const Folded f = fold_with(Method::dg_idw);
    const Mesh& m = coarse();
    const CaseMotion fold = case_motions("wing-body", m).front();
    const std::vector<double> expected = moved_boundary_points(
        m, f.boundary.boundary, resolve_frame(m, fold.spec, f.boundary, 0).motion);
    for (std::size_t i = 0; i < f.boundary.boundary.nodes.size(); ++i)
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(f.mesh.points[3 * f.boundary.boundary.nodes[i] + k], expected[3 * i + k], 1e-9);
    EXPECT_LE(f.after.inverted, 2);                     // measured 1
    EXPECT_GT(f.after.mean, 0.985 * f.before.mean);     // measured 0.8016 against 0.8102
}

TEST(CasesWingBody, SizesAreKnownAndBadOptionsThrow) {
    EXPECT_LT(wing_body_size(1).h_wing, wing_body_size(0).h_wing);
    EXPECT_THROW(wing_body_size(2), MeshError);
    WingBodyOptions o = wing_body_size(0);
    o.h_wing = 0;
    EXPECT_THROW(make_wing_body(o), MeshError);
    EXPECT_EQ(case_size_count("wing-body"), 2);
    EXPECT_THROW(case_motions("wing-body", Mesh{}), MeshError);
}
