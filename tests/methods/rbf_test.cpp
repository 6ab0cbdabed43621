#include "dgwarp/methods/rbf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;
using dgwarp::test::moved;

namespace {

std::vector<double> deform(const RbfPlan& plan, const std::vector<double>& points, const BoundaryMotion& motion,
                           RbfStepReport* report = nullptr) {
    std::vector<double> out(points.size(), std::nan(""));
    const RbfStepReport r = deform_rbf(plan, points, motion, out);
    if (report) *report = r;
    return out;
}


// Per-node motion of the moving nodes: a smooth non-rigid field plus a rotation about the inner centre.
BoundaryMotion wavy_motion(const BoxInBox& m, double amount = 0.05) {
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b) {
        if (!m.boundary.moving[b]) continue;
        const double* x = m.points.data() + m.boundary.nodes[b] * m.dim;
        motion[b].translation = {amount * std::sin(7 * x[1]), amount * std::cos(5 * x[0]),
                                 m.dim == 3 ? amount * std::sin(3 * x[0] + 2 * x[1]) : 0.0};
        motion[b].rotation = {m.dim == 3 ? 0.2 : 0.0, 0, 0.4};
        motion[b].center = m.inner_center;
    }
    return motion;
}

// max_b |s(x_b) - d_b| computed here from evaluate_rbf.
double interpolation_error(const RbfPlan& plan, const RbfCoefficients& c, const BoundaryMotion& motion) {
    const std::vector<double> d = rbf_boundary_displacements(plan, motion);
    std::vector<double> s(d.size());
    evaluate_rbf(plan, c, plan.centre_points, s);
    double worst = 0;
    for (std::size_t b = 0; b < plan.boundary_nodes.size(); ++b) {
        double e2 = 0;
        for (int k = 0; k < plan.dim; ++k) e2 += std::pow(s[b * plan.dim + k] - d[b * plan.dim + k], 2);
        worst = std::max(worst, std::sqrt(e2));
    }
    return worst;
}

}  // namespace

TEST(Rbf, WendlandC2HasItsValuesAndVanishesOutsideTheSupport) {
    EXPECT_EQ(wendland_c2(0), 1.0);
    EXPECT_NEAR(wendland_c2(0.5), 0.0625 * 3, 1e-16);  // (1/2)^4 (2 + 1)
    EXPECT_NEAR(wendland_c2(0.25), std::pow(0.75, 4) * 2, 1e-16);
    EXPECT_EQ(wendland_c2(1.0), 0.0);
    EXPECT_EQ(wendland_c2(1.5), 0.0);
}

TEST(Rbf, FullCentresInterpolateTheBoundaryDisplacements) {
    for (int dim : {2, 3}) {
        const BoxInBox m = test::jittered(box_in_box(dim, dim == 2 ? 24 : 9), 0.005, 3);
        const BoundaryMotion motion = wavy_motion(m);
        for (const RbfOptions options : {RbfOptions{}, RbfOptions{0.35, 0, 0, RbfSolver::automatic}}) {
            const RbfPlan plan = prepare_rbf(dim, m.points, m.boundary, options);
            EXPECT_EQ(plan.dense, options.support_radius == 0);
            const RbfCoefficients c = solve_rbf(plan, motion);
            EXPECT_EQ(c.report.centres, static_cast<std::int64_t>(m.boundary.nodes.size()));
            EXPECT_LT(interpolation_error(plan, c, motion), 1e-10) << dim << "D R " << plan.radius;
            EXPECT_LT(c.report.boundary_error, 1e-10);
        }
    }
}

TEST(Rbf, GreedyReductionOfARigidMotionKeepsOnlyDimPlusOneCentres) {
    // The displacement of a rigid motion is linear in x: the polynomial
    // reproduces it, and the reduction stops at the dim + 1 seed centres.
    // (That every variant moves every node rigidly: method_properties_test.cpp.)
    for (int dim : {2, 3}) {
        BoxInBox m = box_in_box(dim, dim == 2 ? 20 : 8, 2.0);
        std::fill(m.boundary.moving.begin(), m.boundary.moving.end(), std::uint8_t{1});
        NodeMotion rigid{{0.3, -0.7, 0.2}, {0.3, -0.2, 0.5}, {0.9, 1.3, 0.4}};
        if (dim == 2) rigid.rotation[0] = rigid.rotation[1] = rigid.translation[2] = 0;
        const RbfPlan plan = prepare_rbf(dim, m.points, m.boundary, {0, 1e-9, 0, RbfSolver::automatic});
        RbfStepReport report;
        const auto out = deform(plan, m.points, BoundaryMotion(m.boundary.nodes.size(), rigid), &report);
        EXPECT_EQ(report.centres, dim + 1);
        for (std::size_t n = 0; n < m.num_points(); ++n) {
            const auto y = moved(dim, m.points, n, rigid);
            for (int d = 0; d < dim; ++d) ASSERT_NEAR(out[n * dim + d], y[d], 1e-10) << dim << "D node " << n;
        }
    }
}

TEST(Rbf, DenseAndSparseSolversAgree) {
    // The same radius through both paths: global (dense by default) and compact (sparse by default).
    for (int dim : {2, 3}) {
        const BoxInBox m = box_in_box(dim, dim == 2 ? 24 : 9);
        const BoundaryMotion motion = wavy_motion(m);
        for (double radius : {0.0, 0.4}) {
            RbfOptions dense{radius, 0, 0, RbfSolver::dense}, sparse{radius, 0, 0, RbfSolver::sparse};
            const RbfPlan dense_plan = prepare_rbf(dim, m.points, m.boundary, dense);
            const RbfPlan sparse_plan = prepare_rbf(dim, m.points, m.boundary, sparse);
            EXPECT_TRUE(dense_plan.dense);
            EXPECT_FALSE(sparse_plan.dense);
            if (radius > 0) {
                EXPECT_LT(sparse_plan.stats.matrix_nonzeros, dense_plan.stats.matrix_nonzeros);
            }
            const auto a = deform(dense_plan, m.points, motion);
            const auto b = deform(sparse_plan, m.points, motion);
            for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], 1e-10) << dim << "D R " << radius;
        }
    }
}

TEST(Rbf, EvaluationMatchesABruteForceSum) {
    // s(x) = Σ α_j φ(|x - x_j| / R) + β_0 + Σ β_k (x_k - shift_k) / D, summed here with plain loops.
    for (int dim : {2, 3}) {
        const BoxInBox m = box_in_box(dim, dim == 2 ? 16 : 7);
        const BoundaryMotion motion = wavy_motion(m);
        for (double radius : {0.0, 0.3}) {
            const RbfPlan plan = prepare_rbf(dim, m.points, m.boundary, {radius, 0, 0, RbfSolver::automatic});
            const RbfCoefficients c = solve_rbf(plan, motion);
            const auto out = deform(plan, m.points, motion);
            for (NodeId n : m.volume) {
                const double* x = m.points.data() + n * dim;
                for (int k = 0; k < dim; ++k) {
                    double s = c.beta[k];
                    for (int a = 0; a < dim; ++a) s += c.beta[(1 + a) * dim + k] * (x[a] - plan.shift[a]) / plan.diagonal;
                    for (std::size_t j = 0; j < c.centres.size(); ++j) {
                        double r2 = 0;
                        for (int a = 0; a < dim; ++a) r2 += std::pow(x[a] - c.centre_points[j * dim + a], 2);
                        s += c.alpha[j * dim + k] * wendland_c2(std::sqrt(r2) / plan.radius);
                    }
                    ASSERT_NEAR(out[n * dim + k], x[k] + s, 1e-12) << dim << "D node " << n;
                }
            }
        }
    }
}

TEST(Rbf, GreedyReductionKeepsFewerCentresWithinTheTolerance) {
    for (int dim : {2, 3}) {
        const BoxInBox m = box_in_box(dim, dim == 2 ? 30 : 8);
        const BoundaryMotion motion = wavy_motion(m);
        for (double tolerance : {1e-2, 1e-4}) {
            for (double radius : {0.0, 0.5}) {
                SCOPED_TRACE(std::to_string(dim) + "D tolerance " + std::to_string(tolerance) + " R " +
                             std::to_string(radius));
                const RbfPlan plan = prepare_rbf(dim, m.points, m.boundary, {radius, tolerance, 0, RbfSolver::automatic});
                EXPECT_EQ(plan.factorization, nullptr);
                const RbfCoefficients c = solve_rbf(plan, motion);
                EXPECT_GT(c.report.centres, dim + 1);
                EXPECT_LT(c.report.centres, static_cast<std::int64_t>(m.boundary.nodes.size()));
                EXPECT_LE(c.report.boundary_error, tolerance);
                // The reported error is the interpolant's, measured independently.
                EXPECT_NEAR(interpolation_error(plan, c, motion), c.report.boundary_error, 1e-12);
                // The centres are distinct boundary nodes.
                std::vector<std::int32_t> sorted = c.centres;
                std::sort(sorted.begin(), sorted.end());
                EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
            }
        }
        // A tighter tolerance keeps more centres.
        const auto centres = [&](double tolerance) {
            return solve_rbf(prepare_rbf(dim, m.points, m.boundary, {0, tolerance, 0, RbfSolver::automatic}), motion)
                .report.centres;
        };
        EXPECT_LT(centres(1e-1), centres(1e-3));
    }
}

TEST(Rbf, TheDenseSizeGuardNamesTheBytesItWouldNeed) {
    const BoxInBox m = box_in_box(2, 20);
    const std::size_t nb = m.boundary.nodes.size();
    const std::size_t needed = nb * nb * 8 + nb * 6 * 8;
    try {
        prepare_rbf(2, m.points, m.boundary, {0, 0, needed - 1, RbfSolver::automatic});
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(std::to_string(needed) + " bytes"), std::string::npos) << what;
        EXPECT_NE(what.find("greedy"), std::string::npos) << what;
    }
    EXPECT_NO_THROW(prepare_rbf(2, m.points, m.boundary, {0, 0, needed, RbfSolver::automatic}));
    // The sparse path is not limited by it.
    EXPECT_NO_THROW(prepare_rbf(2, m.points, m.boundary, {0.3, 0, needed - 1, RbfSolver::automatic}));
}

TEST(Rbf, RejectsBadInput) {
    const BoxInBox m = box_in_box(2, 12);
    EXPECT_THROW(prepare_rbf(2, m.points, m.boundary, {-1, 0, 0, RbfSolver::automatic}), Error);
    EXPECT_THROW(prepare_rbf(2, m.points, m.boundary, {0, -1, 0, RbfSolver::automatic}), Error);
    EXPECT_THROW(prepare_rbf(2, m.points, BoundarySet{{0, 1}, {1, 0}}), MeshError);
    // Collinear boundary nodes leave the linear polynomial undetermined: full and greedy paths.
    const std::vector<double> line{0, 0, 1, 0, 2, 0, 3, 0, 1.5, 1};
    const BoundarySet on_line{{0, 1, 2, 3}, {1, 0, 0, 1}};
    EXPECT_THROW(prepare_rbf(2, line, on_line), MeshError);
    const RbfPlan greedy = prepare_rbf(2, line, on_line, {0, 1e-6, 0, RbfSolver::automatic});
    BoundaryMotion motion(4);
    motion[0].translation = {0.1, 0.2, 0};
    EXPECT_THROW(solve_rbf(greedy, motion), MeshError);

    const RbfPlan plan = prepare_rbf(2, m.points, m.boundary);
    std::vector<double> out(m.points.size());
    EXPECT_THROW(deform_rbf(plan, m.points, BoundaryMotion(3), out), MeshError);
    std::vector<double> short_out(m.points.size() - 2);
    EXPECT_THROW(deform_rbf(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), short_out), MeshError);
}
