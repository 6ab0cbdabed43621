#include "dgwarp/methods/derivative.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;
using dgwarp::test::jittered;

namespace {

/// A translation per boundary index (zero for static nodes), random.
std::vector<double> random_translations(const BoxInBox& m, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<double> t(m.boundary.nodes.size() * static_cast<std::size_t>(m.dim), 0.0);
    for (std::size_t b = 0; b < m.boundary.nodes.size(); ++b)
        if (m.boundary.moving[b])
            for (int d = 0; d < m.dim; ++d) t[b * m.dim + d] = n(rng);
    return t;
}

BoundaryMotion translation_motion(const BoxInBox& m, const std::vector<double>& t, double scale) {
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b)
        for (int d = 0; d < m.dim; ++d) motion[b].translation[static_cast<std::size_t>(d)] = scale * t[b * m.dim + d];
    return motion;
}

std::vector<Plan> plans_of(const BoxInBox& m) {
    // A denser coarse level than the default, so that DG-harmonic's small box has coarse interior points
    // (its derivative then goes through the coarse solve).
    MethodOptions o;
    o.dg_harmonic.wall_spacing = 2.0;
    o.dg_harmonic.growth = 0.5;
    std::vector<Plan> plans;
    plans.push_back(prepare(Method::dg_idw, m.dim, m.points, m.boundary, o));
    plans.push_back(prepare(Method::dg_harmonic, m.dim, m.points, m.boundary, o));
    EXPECT_GT(std::get<DgHarmonicPlan>(plans.back()).stats.coarse_interior, 0);
    return plans;
}

}  // namespace

// A translation-only step is linear in the translations: J t is the step's
// displacement (to rounding: the step adds it to the points), at any scale.
TEST(DeformDerivative, IsTheStepsDisplacementForTranslations) {
    for (int dim : {2, 3}) {
        const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 24 : 10), 0.02, 3);
        const std::vector<double> t = random_translations(m, 5);
        for (const Plan& plan : plans_of(m)) {
            std::vector<double> jt(m.points.size()), moved(m.points.size());
            deform_derivative(plan, t, jt);
            double largest = 0;
            for (double v : jt) largest = std::max(largest, std::abs(v));
            ASSERT_GT(largest, 0.5);
            for (double scale : {1e-3, 0.02}) {
                deform(plan, m.points, translation_motion(m, t, scale), moved);
                for (std::size_t i = 0; i < jt.size(); ++i)
                    ASSERT_NEAR((moved[i] - m.points[i]) / scale, jt[i], 1e-9 * largest / scale)
                        << method_name(plan_method(plan)) << " " << dim << "D, value " << i;
            }
        }
    }
}

// <J v, w> = <v, Jᵀ w> to round-off, and Jᵀ's rows of static nodes are zero.
TEST(DeformDerivative, TheTransposeIsTheAdjoint) {
    for (int dim : {2, 3}) {
        const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 24 : 10), 0.02, 4);
        const std::vector<double> v = random_translations(m, 6);
        std::mt19937 rng(7);
        std::normal_distribution<double> n(0.0, 1.0);
        std::vector<double> w(m.points.size());
        for (double& x : w) x = n(rng);
        for (const Plan& plan : plans_of(m)) {
            std::vector<double> jv(m.points.size()), jtw(v.size());
            deform_derivative(plan, v, jv);
            deform_derivative_transpose(plan, w, jtw);
            double lhs = 0, rhs = 0, scale = 0;
            for (std::size_t i = 0; i < w.size(); ++i) lhs += jv[i] * w[i], scale += std::abs(jv[i] * w[i]);
            for (std::size_t i = 0; i < v.size(); ++i) rhs += v[i] * jtw[i];
            EXPECT_NEAR(lhs, rhs, 1e-13 * scale) << method_name(plan_method(plan)) << " " << dim << "D";
            for (std::size_t b = 0; b < m.boundary.nodes.size(); ++b) {
                if (m.boundary.moving[b]) continue;
                for (int d = 0; d < dim; ++d) EXPECT_EQ(jtw[b * dim + d], 0.0);
            }
        }
    }
}

TEST(DeformDerivative, RefusesWrongSizesNonFiniteInputAndOtherMethods) {
    const BoxInBox m = box_in_box(2, 12);
    const Plan plan = prepare(Method::dg_idw, 2, m.points, m.boundary);
    std::vector<double> v(m.boundary.nodes.size() * 2, 0.0), out(m.points.size());
    std::vector<double> short_v(v.begin(), v.end() - 1);
    EXPECT_THROW(deform_derivative(plan, short_v, out), MeshError);
    v[3] = std::nan("");
    try {
        deform_derivative(plan, v, out);
        FAIL() << "no error for a NaN";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("row 1 of the input is not finite"), std::string::npos) << e.what();
    }
    const Plan idw = prepare(Method::idw, 2, m.points, m.boundary);
    EXPECT_FALSE(has_deform_derivative(idw));
    std::vector<double> back(v.size());
    EXPECT_THROW(deform_derivative_transpose(idw, out, back), Error);
}
