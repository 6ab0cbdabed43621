#include "dgwarp/methods/idw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;
using dgwarp::test::moved;
using dgwarp::test::random_motion;

namespace {

std::vector<double> deform(const IdwPlan& plan, const std::vector<double>& points, const BoundaryMotion& motion,
                           const IdwOptions& options = {}) {
    std::vector<double> out(points.size(), std::nan(""));
    deform_idw(plan, points, motion, out, options);
    return out;
}



// Eq. 2.1 with plain loops and std::pow, the centre as the moving nodes'
// weighted average, and the node moved by apply_motion (Rodrigues with sin/cos).
std::vector<double> brute_force(const BoxInBox& m, const BoundaryMotion& motion, double cd, double cs, double l) {
    const int dim = m.dim;
    std::vector<double> out = m.points;
    for (NodeId n : m.volume) {
        double den_moving = 0, den_static = 0;
        Vec3 t{}, w{}, c{};
        for (std::size_t b = 0; b < m.boundary.nodes.size(); ++b) {
            const NodeId nb = m.boundary.nodes[b];
            double r2 = 0;
            for (int d = 0; d < dim; ++d) r2 += std::pow(m.points[n * dim + d] - m.points[nb * dim + d], 2);
            const double rho = std::sqrt(r2) / l;
            if (m.boundary.moving[b]) {
                const double q = std::pow(rho, -cd);
                den_moving += q;
                for (int k = 0; k < 3; ++k) {
                    t[k] += q * motion[b].translation[k];
                    w[k] += q * motion[b].rotation[k];
                    c[k] += q * motion[b].center[k];
                }
            } else {
                den_static += std::pow(rho, -cs);
            }
        }
        NodeMotion local;
        for (int k = 0; k < 3; ++k) {
            local.translation[k] = t[k] / (den_moving + den_static);
            local.rotation[k] = w[k] / (den_moving + den_static);
            local.center[k] = c[k] / den_moving;
        }
        apply_motion(local, std::span<const double>(m.points.data() + n * dim, dim),
                     std::span<double>(out.data() + n * dim, dim));
    }
    return out;
}

}  // namespace

TEST(Idw, MatchesABruteForceSumOverAllBoundaryNodes) {
    // Default exponents (3, 5: odd, the square-root path), even ones, and
    // non-integer ones (the std::pow path); auto and explicit L.
    struct Case {
        double cd, cs, l;
    };
    for (int dim : {2, 3}) {
        const BoxInBox m = test::jittered(box_in_box(dim, dim == 2 ? 21 : 8, 1.5), 0.01, 5);
        const IdwPlan plan = prepare_idw(dim, m.points, m.boundary);
        const BoundaryMotion motion = random_motion(m, 21);
        for (const Case c : {Case{3, 5, 0}, Case{2, 4, 0.7}, Case{2.5, 3.7, 0}, Case{1, 8, 0.3}}) {
            SCOPED_TRACE(std::to_string(dim) + "D c_d " + std::to_string(c.cd) + " c_s " + std::to_string(c.cs));
            const IdwOptions options{c.cd, c.cs, c.l};
            const auto out = deform(plan, m.points, motion, options);
            const auto expected = brute_force(m, motion, c.cd, c.cs, c.l > 0 ? c.l : plan.auto_length_scale);
            double largest_move = 0;
            for (NodeId n : m.volume)
                for (int d = 0; d < dim; ++d) {
                    ASSERT_NEAR(out[n * dim + d], expected[n * dim + d], 1e-12) << "node " << n;
                    largest_move = std::max(largest_move, std::abs(out[n * dim + d] - m.points[n * dim + d]));
                }
            EXPECT_GT(largest_move, 1e-3);  // the comparison is not between two unmoved meshes
        }
    }
}

TEST(Idw, AutoLengthScaleIsTheMovingNodesDiagonal) {
    const BoxInBox m = box_in_box(2, 12, 3.0);  // inner box: grid indices 4..8 of 12
    const IdwPlan plan = prepare_idw(2, m.points, m.boundary);
    EXPECT_NEAR(plan.auto_length_scale, std::sqrt(2.0) * 3.0 * 4 / 12, 1e-14);
}

TEST(Idw, WithAutoLengthScaleTheResultDoesNotDependOnTheUnit) {
    for (int dim : {2, 3}) {
        const BoxInBox m = box_in_box(dim, dim == 2 ? 18 : 8, 1.0);
        const BoxInBox big = box_in_box(dim, dim == 2 ? 18 : 8, 1000.0);
        BoundaryMotion motion = random_motion(m, 7), big_motion = motion;
        for (NodeMotion& nm : big_motion)
            for (int k = 0; k < 3; ++k) {
                nm.translation[k] *= 1000;
                nm.center[k] *= 1000;
            }
        const auto out = deform(prepare_idw(dim, m.points, m.boundary), m.points, motion);
        const auto big_out = deform(prepare_idw(dim, big.points, big.boundary), big.points, big_motion);
        for (std::size_t i = 0; i < out.size(); ++i) ASSERT_NEAR(big_out[i] / 1000, out[i], 1e-12) << i;
    }
}

TEST(Idw, AVolumeNodeOnABoundaryNodeTakesItsMotion) {
    // Node 3 sits on moving boundary node 0: its weight dominates, nothing overflows.
    const std::vector<double> points{0, 0, 4, 0, 0, 4, 0, 0, 1, 1};
    const BoundarySet boundary{{0, 1, 2}, {1, 0, 0}};
    const IdwPlan plan = prepare_idw(2, points, boundary);
    BoundaryMotion motion(3);
    motion[0].translation = {0.5, -0.25, 0};
    const auto out = deform(plan, points, motion);
    EXPECT_NEAR(out[6], 0.5, 1e-12);
    EXPECT_NEAR(out[7], -0.25, 1e-12);
    EXPECT_TRUE(std::isfinite(out[8]) && std::isfinite(out[9]));
}

TEST(Idw, WithoutMovingNodesNothingMoves) {
    const BoxInBox m = box_in_box(2, 12);
    BoundarySet still = m.boundary;
    std::fill(still.moving.begin(), still.moving.end(), std::uint8_t{0});
    const IdwPlan plan = prepare_idw(2, m.points, still);
    EXPECT_EQ(deform(plan, m.points, BoundaryMotion(still.nodes.size())), m.points);
}

TEST(Idw, RejectsBadOptionsAndSizes) {
    const BoxInBox m = box_in_box(2, 12);
    EXPECT_THROW(prepare_idw(2, m.points, m.boundary, {0, 5, 0}), Error);
    EXPECT_THROW(prepare_idw(2, m.points, m.boundary, {3, 17, 0}), Error);
    EXPECT_THROW(prepare_idw(2, m.points, m.boundary, {3, 5, -1}), Error);
    EXPECT_THROW(prepare_idw(4, m.points, m.boundary), MeshError);
    EXPECT_THROW(prepare_idw(2, m.points, BoundarySet{}), MeshError);
    BoundarySet unsorted = m.boundary;
    std::swap(unsorted.nodes[0], unsorted.nodes[1]);
    EXPECT_THROW(prepare_idw(2, m.points, unsorted), MeshError);

    const IdwPlan plan = prepare_idw(2, m.points, m.boundary);
    std::vector<double> out(m.points.size());
    EXPECT_THROW(deform_idw(plan, m.points, BoundaryMotion(3), out), MeshError);
    std::vector<double> short_out(m.points.size() - 2);
    EXPECT_THROW(deform_idw(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), short_out), MeshError);
    EXPECT_THROW(deform_idw(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), out, {3, 0, 0}), Error);
}
