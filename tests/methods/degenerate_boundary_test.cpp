// Degenerate boundaries behind the one interface (method.hpp), for every
// method: boundary nodes at the same coordinates (zero-length boundary edges,
// such as a collapsed trailing edge) and no moving boundary node at all (a
// motion that names only empty markers).
#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/methods/method.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;

namespace {

/// `m` with a copy of the boundary node at boundary index `b` appended as a
/// new boundary node (its id is the largest, so the set stays sorted), flagged `moving`.
test::BoxInBox with_copy_of(test::BoxInBox m, std::size_t b, bool moving) {
    const auto node = static_cast<std::size_t>(m.boundary.nodes[b]);
    const auto id = static_cast<NodeId>(m.num_points());
    for (int d = 0; d < m.dim; ++d) m.points.push_back(m.points[node * m.dim + d]);
    m.boundary.nodes.push_back(id);
    m.boundary.moving.push_back(moving ? 1 : 0);
    return m;
}

/// The first boundary index flagged `moving`.
std::size_t first_boundary_index(const test::BoxInBox& m, bool moving) {
    for (std::size_t b = 0; b < m.boundary.moving.size(); ++b)
        if ((m.boundary.moving[b] != 0) == moving) return b;
    ADD_FAILURE() << "no such boundary node";
    return 0;
}

/// The inner box translated by t: one motion per boundary node.
BoundaryMotion translation(const test::BoxInBox& m, const Vec3& t) {
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b)
        if (m.boundary.moving[b]) motion[b].translation = t;
    return motion;
}

}  // namespace

TEST(DegenerateBoundary, EveryMethodWorksWithBoundaryNodesAtTheSameCoordinates) {
    for (int dim : {2, 3}) {
        const test::BoxInBox plain = test::box_in_box(dim, dim == 2 ? 12 : 6);
        const Vec3 t{0.02, -0.01, dim == 3 ? 0.015 : 0.0};
        // A moving and a static node, each duplicated with the same flag.
        const test::BoxInBox twice =
            with_copy_of(with_copy_of(plain, first_boundary_index(plain, true), true), first_boundary_index(plain, false),
                         false);
        ASSERT_EQ(twice.num_points(), plain.num_points() + 2);
        for (Method method : all_methods) {
            if (method_needs_cells(method)) continue;  // point sets without cells
            SCOPED_TRACE(std::string(method_name(method)) + " " + std::to_string(dim) + "D");
            std::vector<double> expected(plain.points.size()), out(twice.points.size());
            deform(prepare(method, dim, plain.points, plain.boundary), plain.points, translation(plain, t), expected);
            const Plan plan = prepare(method, dim, twice.points, twice.boundary);
            const StepReport report = deform(plan, twice.points, translation(twice, t), out);
            EXPECT_EQ(report.conflicting_shared_vertices, 0);
            // Every boundary node, copies included, moves with its own motion.
            for (std::size_t b = 0; b < twice.boundary.nodes.size(); ++b) {
                const auto node = static_cast<std::size_t>(twice.boundary.nodes[b]);
                for (int d = 0; d < dim; ++d)
                    EXPECT_DOUBLE_EQ(out[node * dim + d], twice.points[node * dim + d] + (twice.boundary.moving[b] ? t[d] : 0));
            }
            for (NodeId v : twice.volume) {
                const auto node = static_cast<std::size_t>(v);
                if (method == Method::idw) {
                    // IDW sums over every boundary node (a copy counts twice): still a
                    // blend of the two motions, 0 and t, in the same direction.
                    double along = 0, t2 = 0;
                    for (int d = 0; d < dim; ++d) {
                        along += (out[node * dim + d] - twice.points[node * dim + d]) * t[d];
                        t2 += t[d] * t[d];
                    }
                    EXPECT_GE(along / t2, 0.0);
                    EXPECT_LE(along / t2, 1.0 + 1e-12);
                } else {
                    // DG-IDW, DGM (one graph vertex) and RBF (one centre) see the copies as one node.
                    for (int d = 0; d < dim; ++d) EXPECT_NEAR(out[node * dim + d], expected[node * dim + d], 1e-12);
                }
            }
        }
    }
}

TEST(DegenerateBoundary, CopiesGivenDifferentMotionsAreCountedAndEachFollowsItsOwn) {
    const test::BoxInBox plain = test::box_in_box(2, 12);
    const std::size_t mover = first_boundary_index(plain, true);
    // The copy of a moving node is static: a collapsed trailing edge whose lower node is held.
    const test::BoxInBox m = with_copy_of(plain, mover, false);
    const Vec3 t{0.02, 0.01, 0};
    for (Method method : all_methods) {
        if (method_needs_cells(method)) continue;  // point sets without cells
        SCOPED_TRACE(std::string(method_name(method)));
        std::vector<double> out(m.points.size());
        const StepReport report = deform(prepare(method, 2, m.points, m.boundary), m.points, translation(m, t), out);
        EXPECT_EQ(report.conflicting_shared_vertices, method == Method::idw ? 0 : 1);
        const auto copy = static_cast<std::size_t>(m.boundary.nodes.back());
        const auto node = static_cast<std::size_t>(m.boundary.nodes[mover]);
        EXPECT_EQ(out[2 * copy], m.points[2 * copy]);  // the static copy stays
        EXPECT_DOUBLE_EQ(out[2 * node], m.points[2 * node] + t[0]);
        for (double x : out) EXPECT_TRUE(std::isfinite(x));
    }
}

TEST(DegenerateBoundary, WithoutAMovingBoundaryNodeNothingMoves) {
    // What a motion naming only empty markers leaves: every boundary node static.
    test::BoxInBox m = test::box_in_box(2, 12);
    std::fill(m.boundary.moving.begin(), m.boundary.moving.end(), 0);
    for (Method method : all_methods) {
        if (method_needs_cells(method)) continue;  // point sets without cells
        SCOPED_TRACE(std::string(method_name(method)));
        std::vector<double> out(m.points.size());
        deform(prepare(method, 2, m.points, m.boundary), m.points, BoundaryMotion(m.boundary.nodes.size()), out);
        EXPECT_EQ(out, m.points);
    }
}
