#include "dgwarp/methods/dg_idw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"
#include "support/dg_idw_deformed.hpp"

using namespace dgwarp;
using dgwarp::test::all_moving;
using dgwarp::test::box_in_box;
using dgwarp::test::dg_idw_deformed;
using dgwarp::test::BoxInBox;
using dgwarp::test::moved;
using dgwarp::test::random_motion;

namespace {

/// `plan` with another L (deform uses the plan's options).
DgIdwPlan with_length_scale(DgIdwPlan plan, double length_scale) {
    plan.options.length_scale = length_scale;
    return plan;
}

}  // namespace

// ---- One simplex, every moving/static combination, METHODS.md's formula by hand ----

namespace {

// The interpolated component s for a volume node at distances r[k] (already
// divided by L) from the corners, moving corners in `mask`, corner values s[k]:
// eq. (2.3) in 2D and (2.4) in 3D, case by case.
double paper_component(int dim, double a, unsigned mask, const double* r, const double* s) {
    std::vector<int> moving, fixed;
    for (int k = 0; k <= dim; ++k) (mask >> k & 1 ? moving : fixed).push_back(k);
    auto r2 = [&](int k) { return 1.0 / (r[k] * r[k]); };  // r^-2
    auto r1 = [&](int k) { return 1.0 / r[k]; };           // r^-1
    const int d0 = moving.empty() ? 0 : moving[0];
    if (dim == 2) {
        switch (moving.size()) {
            case 0: return 0.0;  // no moving corner: the node stays
            case 1: {            // n_d = 1, n_s = 2: "2a"
                const int s1 = fixed[0], s2 = fixed[1];
                return 2 * a * s[d0] * r2(d0) / (2 * a * r2(d0) + r1(s1) + r1(s2));
            }
            case 2: {  // n_d = 2, n_s = 1: "2 r_s^-1"
                const int d1 = moving[1], st = fixed[0];
                return a * (s[d0] * r2(d0) + s[d1] * r2(d1)) / (a * (r2(d0) + r2(d1)) + 2 * r1(st));
            }
            default: {  // n_s = 0: general formula with no static term
                return a * (s[0] * r2(0) + s[1] * r2(1) + s[2] * r2(2)) / (a * (r2(0) + r2(1) + r2(2)));
            }
        }
    }
    switch (moving.size()) {
        case 0: return 0.0;
        case 1: {  // n_d = 1, n_s = 3: "3a"
            const int s1 = fixed[0], s2 = fixed[1], s3 = fixed[2];
            return 3 * a * s[d0] * r2(d0) / (3 * a * r2(d0) + r1(s1) + r1(s2) + r1(s3));
        }
        case 2: {  // n_d = 2, n_s = 2: the general formula
            const int d1 = moving[1], s1 = fixed[0], s2 = fixed[1];
            return a * (s[d0] * r2(d0) + s[d1] * r2(d1)) / (a * (r2(d0) + r2(d1)) + r1(s1) + r1(s2));
        }
        case 3: {  // n_d = 3, n_s = 1: "3 r_s^-1"
            const int d1 = moving[1], d2 = moving[2], st = fixed[0];
            return a * (s[d0] * r2(d0) + s[d1] * r2(d1) + s[d2] * r2(d2)) /
                   (a * (r2(d0) + r2(d1) + r2(d2)) + 3 * r1(st));
        }
        default: {  // n_s = 0
            return a * (s[0] * r2(0) + s[1] * r2(1) + s[2] * r2(2) + s[3] * r2(3)) /
                   (a * (r2(0) + r2(1) + r2(2) + r2(3)));
        }
    }
}

struct OneSimplex {
    int dim;
    std::vector<double> points;  // corners 0..dim, then the volume node
    BoundarySet boundary;
};

OneSimplex one_simplex(int dim, unsigned mask, double scale = 1.0) {
    OneSimplex s{dim, {}, {}};
    s.points = dim == 2 ? std::vector<double>{0, 0, 2, 0.2, 0.5, 1.7, 0.8, 0.6}
                        : std::vector<double>{0, 0, 0, 2, 0.1, 0.2, 0.3, 1.8, -0.1, 0.2, 0.4, 1.9, 0.6, 0.5, 0.4};
    for (double& x : s.points) x *= scale;
    for (int k = 0; k <= dim; ++k) {
        s.boundary.nodes.push_back(k);
        s.boundary.moving.push_back(mask >> k & 1);
    }
    return s;
}

}  // namespace

TEST(DgIdw, OneSimplexTranslationMatchesThePaperFormulaForEveryMovingSet) {
    for (int dim : {2, 3}) {
        for (const double length : {1.0, 2.5}) {
            for (unsigned mask = 0; mask < (1u << (dim + 1)); ++mask) {
                const OneSimplex s = one_simplex(dim, mask);
                const DgIdwPlan plan = prepare_dg_idw(dim, s.points, s.boundary);
                BoundaryMotion motion(dim + 1);
                double tx[4], ty[4], tz[4], r[4];
                const double* x = s.points.data() + dim * (dim + 1);
                for (int k = 0; k <= dim; ++k) {
                    if (mask >> k & 1) motion[k].translation = {0.1 * (k + 1), -0.05 * (k + 2), 0.03 * (3 - k)};
                    tx[k] = motion[k].translation[0];
                    ty[k] = motion[k].translation[1];
                    tz[k] = motion[k].translation[2];
                    double sq = 0;
                    for (int d = 0; d < dim; ++d) sq += (x[d] - s.points[k * dim + d]) * (x[d] - s.points[k * dim + d]);
                    r[k] = std::sqrt(sq) / length;  // distances divided by L
                }
                const auto out = dg_idw_deformed(with_length_scale(plan, length), s.points, motion);
                const double* y = out.data() + dim * (dim + 1);
                EXPECT_NEAR(y[0] - x[0], paper_component(dim, 7.0, mask, r, tx), 1e-14) << dim << "D mask " << mask;
                EXPECT_NEAR(y[1] - x[1], paper_component(dim, 7.0, mask, r, ty), 1e-14) << dim << "D mask " << mask;
                if (dim == 3) {
                    EXPECT_NEAR(y[2] - x[2], paper_component(dim, 7.0, mask, r, tz), 1e-14) << "mask " << mask;
                }
            }
        }
    }
}

TEST(DgIdw, OneSimplexRotationMatchesThePaperFormulaForEveryMovingSet) {
    for (int dim : {2, 3}) {
        for (unsigned mask = 0; mask < (1u << (dim + 1)); ++mask) {
            const OneSimplex s = one_simplex(dim, mask);
            const DgIdwPlan plan = prepare_dg_idw(dim, s.points, s.boundary);
            BoundaryMotion motion(dim + 1);
            double w[3][4] = {}, r[4];
            const double* x = s.points.data() + dim * (dim + 1);
            for (int k = 0; k <= dim; ++k) {
                if (mask >> k & 1) {
                    motion[k].rotation = {dim == 3 ? 0.2 * (k + 1) : 0, dim == 3 ? -0.1 * k : 0, 0.15 * (k + 2)};
                    motion[k].center = {0.3 * k, 0.1 + 0.2 * k, dim == 3 ? -0.1 * k : 0};
                }
                for (int j = 0; j < 3; ++j) w[j][k] = motion[k].rotation[j];
                double sq = 0;
                for (int d = 0; d < dim; ++d) sq += (x[d] - s.points[k * dim + d]) * (x[d] - s.points[k * dim + d]);
                r[k] = std::sqrt(sq);
            }
            // Interpolated rotation vector (a = 1.4), and the centre: the moving
            // corners' centres averaged with weights r^-2 (normalised over them).
            NodeMotion expected;
            for (int j = 0; j < 3; ++j) expected.rotation[j] = paper_component(dim, 1.4, mask, r, w[j]);
            double sum = 0;
            for (int k = 0; k <= dim; ++k)
                if (mask >> k & 1) {
                    sum += 1 / (r[k] * r[k]);
                    for (int d = 0; d < 3; ++d) expected.center[d] += motion[k].center[d] / (r[k] * r[k]);
                }
            for (int d = 0; d < 3 && sum > 0; ++d) expected.center[d] /= sum;
            const auto y_expected = moved(dim, s.points, dim + 1, expected);

            const auto out = dg_idw_deformed(plan, s.points, motion);
            for (int d = 0; d < dim; ++d)
                EXPECT_NEAR(out[dim * (dim + 1) + d], y_expected[d], 1e-14) << dim << "D mask " << mask;
            if (mask != 0) {  // the node does rotate
                EXPECT_GT(std::abs(out[dim * (dim + 1)] - x[0]) + std::abs(out[dim * (dim + 1) + 1] - x[1]), 1e-4);
            }
        }
    }
}

TEST(DgIdw, LengthScaleMakesTheDeformationScaleInvariant) {
    for (int dim : {2, 3}) {
        // Jittered: a grid's Delaunay graph is not unique, and CGAL may break the
        // ties differently once the coordinates are scaled with rounding.
        const BoxInBox small = dgwarp::test::jittered(box_in_box(dim, dim == 2 ? 24 : 9, 1.0), 0.01, 15);
        BoxInBox big = small;
        for (double& x : big.points) x *= 1000;
        const BoundaryMotion motion_small = random_motion(small, 14);
        BoundaryMotion motion_big = motion_small;
        for (NodeMotion& m : motion_big)
            for (int d = 0; d < 3; ++d) {
                m.translation[d] *= 1000;
                m.center[d] *= 1000;
            }
        const DgIdwPlan plan_small = prepare_dg_idw(dim, small.points, small.boundary);
        const DgIdwPlan plan_big = prepare_dg_idw(dim, big.points, big.boundary);
        auto max_relative_gap = [&](double l_small, double l_big) {
            const auto a = dg_idw_deformed(with_length_scale(plan_small, l_small), small.points, motion_small);
            const auto b = dg_idw_deformed(with_length_scale(plan_big, l_big), big.points, motion_big);
            double gap = 0;
            for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, std::abs(b[i] / 1000 - a[i]));
            return gap;
        };
        EXPECT_LT(max_relative_gap(0.37, 370), 1e-12) << dim << "D";
        EXPECT_LT(max_relative_gap(0, 0), 1e-12) << dim << "D (auto L)";
        // The paper's formula (L = 1 in both units) is not scale invariant.
        EXPECT_GT(max_relative_gap(1, 1), 1e-4) << dim << "D";
    }
}

namespace {

// Brute force: the shortest distance between a moving and a static boundary node.
double brute_force_gap(const BoxInBox& m) {
    double gap = std::numeric_limits<double>::infinity();
    const auto& b = m.boundary;
    for (std::size_t i = 0; i < b.nodes.size(); ++i)
        for (std::size_t j = 0; j < b.nodes.size(); ++j) {
            if (!b.moving[i] || b.moving[j]) continue;
            double d2 = 0;
            for (int d = 0; d < m.dim; ++d) {
                const double e = m.points[b.nodes[i] * m.dim + d] - m.points[b.nodes[j] * m.dim + d];
                d2 += e * e;
            }
            gap = std::min(gap, std::sqrt(d2));
        }
    return gap;
}

}  // namespace

TEST(DgIdw, AutoLengthScaleIsTheMovingDiagonalWhenTheGapIsWide) {
    // Inner box: grid indices [8, 16] of 24 in 2D, [3, 6] of 9 in 3D, times size 2;
    // small a's make gap / a (6.7) larger than the diagonal.
    const DgIdwOptions small_a{.a_translation = 0.1, .a_rotation = 0.05};
    const BoxInBox m2 = box_in_box(2, 24, 2.0), m3 = box_in_box(3, 9, 2.0);
    EXPECT_NEAR(prepare_dg_idw(2, m2.points, m2.boundary, small_a).auto_length_scale, 2.0 * std::sqrt(2.0) * 8 / 24,
                1e-15);
    EXPECT_NEAR(prepare_dg_idw(3, m3.points, m3.boundary, small_a).auto_length_scale, 2.0 * std::sqrt(3.0) * 3 / 9,
                1e-15);
}

TEST(DgIdw, AutoLengthScaleFitsTheFollowingZoneInTheGap) {
    // With the paper's a, gap / 7 (0.67 / 7) is below the diagonal; a_rotation above
    // a_translation takes over. The gap is checked against brute force on jittered points.
    for (int dim : {2, 3}) {
        const BoxInBox m = dgwarp::test::jittered(box_in_box(dim, dim == 2 ? 24 : 9, 2.0), 0.02, 7);
        const double gap = brute_force_gap(m);
        EXPECT_LT(gap, 2.0 * 8 / 24 + 0.1);
        EXPECT_NEAR(prepare_dg_idw(dim, m.points, m.boundary).auto_length_scale, gap / 7, 1e-15) << dim << "D";
        EXPECT_NEAR(prepare_dg_idw(dim, m.points, m.boundary, {.a_rotation = 12.5}).auto_length_scale, gap / 12.5,
                    1e-15)
            << dim << "D";
    }
}

TEST(DgIdw, AutoLengthScaleWithoutStaticNodesIsTheDiagonal) {
    const BoxInBox m = all_moving(box_in_box(3, 9, 2.0));
    EXPECT_NEAR(prepare_dg_idw(3, m.points, m.boundary).auto_length_scale, 2.0 * std::sqrt(3.0), 1e-15);
}

TEST(DgIdw, NodeOnAGraphVertexTakesItsMotion) {
    // A triangle of moving corners in a static square; volume nodes 7 and 8 sit
    // exactly on corner 4 (moving) and corner 0 (static).
    const std::vector<double> pts = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1.5, 1.5, 3, 1, 1, 0, 0, 2, 2};
    const BoundarySet boundary{{0, 1, 2, 3, 4, 5, 6}, {0, 0, 0, 0, 1, 1, 1}};
    const DgIdwPlan plan = prepare_dg_idw(2, pts, boundary);
    EXPECT_EQ(plan.stats.snapped_count, 2);
    BoundaryMotion motion(7);
    for (int b = 4; b < 7; ++b) motion[b] = {{0.1 * b, -0.2, 0}, {0, 0, 0.1 * b}, {1.5, 2, 0}};
    const auto out = dg_idw_deformed(plan, pts, motion);
    const auto y = moved(2, pts, 4, motion[4]);
    EXPECT_NEAR(out[14], y[0], 1e-15);
    EXPECT_NEAR(out[15], y[1], 1e-15);
    EXPECT_EQ(out[16], 0.0);
    EXPECT_EQ(out[17], 0.0);
    EXPECT_TRUE(std::isfinite(out[18]) && std::isfinite(out[19]));
}

TEST(DgIdw, SharedVerticesTakeTheFirstMovingNodesMotionAndConflictsAreCounted) {
    // Nodes 7 and 8 repeat the coordinates of node 4 (moving) and node 0 (static).
    const std::vector<double> pts = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1.5, 1.5, 3, 1, 1, 0, 0, 2, 2, 1.2, 1.4};
    const BoundarySet boundary{{0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 0, 0, 0, 1, 1, 1, 1, 1}};
    const DgIdwPlan plan = prepare_dg_idw(2, pts, boundary);
    EXPECT_EQ(plan.stats.shared_vertex_count, 2);
    BoundaryMotion motion(9);
    for (int b = 4; b < 9; ++b) motion[b] = {{0.1 * b, -0.2, 0}, {0, 0, 0.05 * b}, {1.5, 2, 0}};
    const auto out = dg_idw_deformed(plan, pts, motion);
    // Both shared vertices conflict: 4 and 7 differ; 0 is static and 8 moves.
    std::vector<double> scratch(pts.size());
    EXPECT_EQ(deform_dg_idw(plan, pts, motion, scratch).conflicting_shared_vertices, 2);
    // Every boundary node follows its own motion.
    for (int b : {4, 7, 8}) {
        const auto y = moved(2, pts, b, motion[b]);
        EXPECT_EQ(out[2 * b], y[0]);
        EXPECT_EQ(out[2 * b + 1], y[1]);
    }
    // The volume nodes used motion[4] for the shared vertex: giving node 7 that
    // motion changes nothing for them, giving node 4 node 7's motion does.
    BoundaryMotion agree = motion;
    agree[7] = motion[4];
    const auto same = dg_idw_deformed(plan, pts, agree);
    EXPECT_EQ(same[18], out[18]);
    EXPECT_EQ(same[20], out[20]);
    EXPECT_EQ(deform_dg_idw(plan, pts, agree, scratch).conflicting_shared_vertices, 1);
    BoundaryMotion other = motion;
    other[4] = motion[7];
    EXPECT_NE(dg_idw_deformed(plan, pts, other)[20], out[20]);
}

TEST(DgIdw, NodesOutsideTheHullAreCountedAndStillMoveRigidly) {
    BoxInBox m = all_moving(box_in_box(2, 12));
    const std::size_t n0 = m.num_points();
    m.points.insert(m.points.end(), {1.3, 0.5, -0.2, -0.4});  // two nodes outside [0,1]^2
    const DgIdwPlan plan = prepare_dg_idw(2, m.points, m.boundary);
    EXPECT_EQ(plan.stats.outside_count, 2);
    const NodeMotion rigid{{0.1, 0.2, 0}, {0, 0, 0.4}, {0.5, 0.5, 0}};
    const auto out = dg_idw_deformed(plan, m.points, BoundaryMotion(m.boundary.nodes.size(), rigid));
    for (std::size_t n = n0; n < n0 + 2; ++n) {
        const auto y = moved(2, m.points, n, rigid);
        EXPECT_NEAR(out[2 * n], y[0], 1e-12);
        EXPECT_NEAR(out[2 * n + 1], y[1], 1e-12);
    }
}

TEST(DgIdw, WrongSizesAndOptionsAreRefused) {
    const BoxInBox m = box_in_box(2, 12);
    const DgIdwPlan plan = prepare_dg_idw(2, m.points, m.boundary);
    const BoundaryMotion motion(m.boundary.nodes.size());
    std::vector<double> out(m.points.size());
    const std::vector<double> short_points(m.points.begin(), m.points.end() - 2);
    EXPECT_THROW(deform_dg_idw(plan, short_points, motion, out), MeshError);
    std::vector<double> short_out(out.size() - 1);
    EXPECT_THROW(deform_dg_idw(plan, m.points, motion, short_out), MeshError);
    EXPECT_THROW(deform_dg_idw(plan, m.points, BoundaryMotion(motion.size() - 1), out), MeshError);
    DgIdwPlan zero_a = plan;
    zero_a.options.a_translation = 0;
    EXPECT_THROW(deform_dg_idw(zero_a, m.points, motion, out), Error);
    EXPECT_THROW(deform_dg_idw(with_length_scale(plan, -1), m.points, motion, out), Error);
    BoundaryMotion not_finite = motion;
    not_finite[3].translation[1] = std::nan("");
    try {
        deform_dg_idw(plan, m.points, not_finite, out);
        ADD_FAILURE();
    } catch (const MeshError& e) {
        EXPECT_EQ(e.index(), m.boundary.nodes[3]);
    }
    BoundarySet unsorted = m.boundary;
    std::swap(unsorted.nodes[0], unsorted.nodes[1]);
    EXPECT_THROW(prepare_dg_idw(2, m.points, unsorted), MeshError);
    BoundarySet short_flags = m.boundary;
    short_flags.moving.pop_back();
    EXPECT_THROW(prepare_dg_idw(2, m.points, short_flags), MeshError);
}

TEST(DgIdw, APlanRefusesAnotherMesh) {
    const BoxInBox m = box_in_box(3, 6);
    const DgIdwPlan plan = prepare_dg_idw(3, m.points, m.boundary);
    EXPECT_NO_THROW(check_plan_fits(plan, m.points, m.boundary));
    const BoxInBox other = box_in_box(3, 7);
    try {
        check_plan_fits(plan, other.points, other.boundary);
        FAIL();
    } catch (const MeshError& e) {
        const std::string expected = "another mesh (" + std::to_string(m.num_points()) + " points vs " +
                                     std::to_string(other.num_points());
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    std::vector<double> shifted = m.points;
    shifted[5] += 1e-9;
    EXPECT_THROW(check_plan_fits(plan, shifted, m.boundary), MeshError);
    BoundarySet flags = m.boundary;
    flags.moving[0] ^= 1;
    EXPECT_THROW(check_plan_fits(plan, m.points, flags), MeshError);
}
