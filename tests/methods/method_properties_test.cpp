// The properties every deformation method has (STYLE.md: exact boundary
// motion, rigid motions stay rigid, zero motion is the identity, results do
// not depend on the thread count), checked through the common interface
// (method.hpp) for every Method and its option variants, in 2D and 3D.
// What only one method does is tested in its own file.
#include <gtest/gtest.h>

#include <cmath>
#include <chrono>
#include <cstring>
#include <limits>
#include <mutex>
#include <ostream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/method.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::BoxInBox;

/// One method with one set of options.
struct MethodVariant {
    std::string name;  // the test name's suffix
    Method method;
    /// The options for a box of side `size` (RBF's support radius scales with it).
    MethodOptions (*options)(double size);
    /// The size of a per-node motion the method follows without folding its graph.
    double motion_amount = 0.05;
    /// How close a rigid motion of the whole boundary comes out rigid (mesh units, box of side 2).
    double rigid_tolerance = 2e-12;
    /// Whether the test grids are jittered, which removes their cospherical
    /// point sets (DG-harmonic's tests always ran on jittered grids).
    bool jitter = false;
};

// gtest prints a failing test's parameter with this.
void PrintTo(const MethodVariant& v, std::ostream* out) { *out << v.name; }

namespace {

MethodOptions options_default(double) { return {}; }
MethodOptions options_continuous_weights(double) {
    MethodOptions o;
    o.dg_idw.weighting = DgIdwWeighting::continuous;
    return o;
}
MethodOptions options_rbf_compact(double size) {
    MethodOptions o;
    o.rbf.support_radius = 0.3 * size;
    return o;
}
MethodOptions options_rbf_greedy(double) {
    MethodOptions o;
    o.rbf.greedy_tolerance = 1e-3;
    return o;
}
// A denser coarse level than the default, so that the small test boxes have
// coarse interior points (the default keeps none on them).
MethodOptions options_dense_coarse_level(double) {
    MethodOptions o;
    o.dg_harmonic.wall_spacing = 2.0;
    o.dg_harmonic.growth = 0.5;
    return o;
}

const MethodVariant method_variants[] = {
    {"dg_idw", Method::dg_idw, options_default},
    {"dg_idw_continuous", Method::dg_idw, options_continuous_weights},
    {"dgm", Method::dgm, options_default, 0.01},
    {"idw", Method::idw, options_default},
    {"rbf", Method::rbf, options_default, 0.05, 1e-10},
    {"rbf_compact", Method::rbf, options_rbf_compact, 0.05, 1e-10},
    {"rbf_greedy", Method::rbf, options_rbf_greedy, 0.05, 1e-10},
    {"dg_harmonic", Method::dg_harmonic, options_dense_coarse_level, 0.05, 2e-12, true},
};

int property_grid(int dim) { return dim == 2 ? 24 : 9; }

}  // namespace

class MethodProperties : public ::testing::TestWithParam<MethodVariant> {
protected:
    const MethodVariant& variant() const { return GetParam(); }

    /// A box in a box of side `size`; for the variants that want it, its grid
    /// jittered by a fifth of the spacing (no cospherical point sets).
    BoxInBox property_box(int dim, int n, double size = 1.0) const {
        const BoxInBox m = test::box_in_box(dim, n, size);
        return variant().jitter ? test::jittered(m, 0.2 * size / n, 7) : m;
    }

    Plan prepare_for(const BoxInBox& m, double size = 1.0) const {
        return prepare(variant().method, m.dim, m.points, m.boundary, variant().options(size));
    }

    /// One step into a fresh array (NaN-filled, so a node left unwritten shows).
    std::vector<double> step(const Plan& plan, const BoxInBox& m, const BoundaryMotion& motion,
                             StepReport* report = nullptr, double size = 1.0) const {
        std::vector<double> out(m.points.size(), std::nan(""));
        const StepReport r = deform(plan, m.points, motion, out, variant().options(size));
        if (report) *report = r;
        return out;
    }
};

namespace {

/// Where the boundary nodes of `m` go under `motion` (apply_motion), the static ones staying.
void expect_boundary_follows(const BoxInBox& m, const BoundaryMotion& motion, const std::vector<double>& out) {
    const int dim = m.dim;
    for (std::size_t b = 0; b < m.boundary.nodes.size(); ++b) {
        const auto n = static_cast<std::size_t>(m.boundary.nodes[b]);
        const auto y = m.boundary.moving[b]
                           ? test::moved(dim, m.points, n, motion[b])
                           : std::vector<double>(m.points.begin() + n * dim, m.points.begin() + (n + 1) * dim);
        for (int d = 0; d < dim; ++d) ASSERT_EQ(out[n * dim + d], y[d]) << dim << "D boundary node " << n;
    }
}

}  // namespace

TEST_P(MethodProperties, ZeroMotionIsTheIdentityBitForBit) {
    for (int dim : {2, 3}) {
        const double size = 3.7;
        const BoxInBox m = property_box(dim, property_grid(dim), size);
        const Plan plan = prepare_for(m, size);
        EXPECT_EQ(plan_method(plan), variant().method);
        EXPECT_GT(plan_memory_bytes(plan), 0u);
        if (variant().method == Method::dg_harmonic) {
            EXPECT_GT(plan_summary(plan).coarse_points, 10) << dim << "D";
        }
        StepReport report;
        const auto out = step(plan, m, BoundaryMotion(m.boundary.nodes.size()), &report, size);
        EXPECT_EQ(std::memcmp(out.data(), m.points.data(), out.size() * sizeof(double)), 0) << dim << "D";
        EXPECT_EQ(report.substeps, 1);
        EXPECT_EQ(report.invalid_graph_simplices, 0);
    }
}

TEST_P(MethodProperties, BoundaryNodesMoveExactlyAsApplyMotionSays) {
    for (int dim : {2, 3}) {
        const BoxInBox m = property_box(dim, property_grid(dim));
        const BoundaryMotion motion = test::random_motion(m, 11, variant().motion_amount);
        const auto out = step(prepare_for(m), m, motion);
        expect_boundary_follows(m, motion, out);
        // Volume nodes moved, and stayed finite.
        double largest = 0;
        for (NodeId n : m.volume)
            for (int d = 0; d < dim; ++d) {
                ASSERT_TRUE(std::isfinite(out[n * dim + d])) << dim << "D node " << n;
                largest = std::max(largest, std::abs(out[n * dim + d] - m.points[n * dim + d]));
            }
        EXPECT_GT(largest, 1e-3) << dim << "D";
    }
}

TEST_P(MethodProperties, ARigidMotionOfEveryBoundaryNodeMovesEveryNodeRigidly) {
    // Rotation angles below and above 1 rad (both branches of DG-IDW's
    // rotation factors) and up to 2.7 rad (a rigid motion folds no simplex).
    for (int dim : {2, 3}) {
        const double size = 2.0;
        const BoxInBox m = test::all_moving(property_box(dim, property_grid(dim), size));
        const Plan plan = prepare_for(m, size);
        for (const Vec3 w : {Vec3{0.3, -0.2, 0.5}, Vec3{1.1, 0.9, -1.7}, Vec3{0, 0, 2.7}}) {
            NodeMotion rigid{{0.3, -0.7, 0.2}, w, {0.9, 1.3, 0.4}};
            if (dim == 2) rigid.rotation[0] = rigid.rotation[1] = rigid.translation[2] = rigid.center[2] = 0;
            const BoundaryMotion motion(m.boundary.nodes.size(), rigid);
            StepReport report;
            const auto out = step(plan, m, motion, &report, size);
            EXPECT_EQ(report.invalid_graph_simplices, 0);
            for (std::size_t n = 0; n < m.num_points(); ++n) {
                const auto y = test::moved(dim, m.points, n, rigid);
                for (int d = 0; d < dim; ++d)
                    ASSERT_NEAR(out[n * dim + d], y[d], variant().rigid_tolerance) << dim << "D node " << n;
            }
            expect_boundary_follows(m, motion, out);
        }
    }
}

TEST_P(MethodProperties, OneAndTwoThreadsGiveTheSameBits) {
    // In 2D a box large enough that two threads split the step: DG-IDW and
    // dg-harmonic hand out blocks of 16,384 nodes (DGM's graph folds on so
    // fine a grid under this motion: it keeps the small box).
    const bool dgm = variant().method == Method::dgm;
    for (int dim : {2, 3}) {
        // Volume counts that are not multiples of a vector's lane count.
        const BoxInBox m = property_box(dim, dim == 3 ? 15 : dgm ? 61 : 211);
        // The inner box turned by 0.3 rad and shifted (per-node random
        // motions of that size would fold DGM's graph on this fine grid).
        BoundaryMotion motion(m.boundary.nodes.size());
        for (std::size_t b = 0; b < motion.size(); ++b)
            if (m.boundary.moving[b])
                motion[b] = NodeMotion{{0.01, -0.02, dim == 3 ? 0.01 : 0},
                                       {dim == 3 ? 0.1 : 0, dim == 3 ? 0.2 : 0, 0.3}, m.inner_center};
        const int threads = num_threads();
        set_num_threads(1);
        const auto one = step(prepare_for(m), m, motion);
        set_num_threads(2);
        const Plan two_plan = prepare_for(m);
        const auto two = step(two_plan, m, motion);
        // The methods whose step reports per block of nodes report from the
        // threads that finish the blocks: on the 2D box, two of them (a busy
        // machine may leave one thread idle through a step: a few tries).
        std::set<std::thread::id> reporters;
        std::mutex lock;
        std::vector<double> reported(m.points.size());
        for (int attempt = 0; attempt < 10 && reporters.size() < 2; ++attempt)
            deform(two_plan, m.points, motion, reported, variant().options(1.0), [&](double) {
                {
                    const std::lock_guard<std::mutex> hold(lock);
                    reporters.insert(std::this_thread::get_id());
                }
                // The reporting thread pauses, so that the other one takes
                // the next block even on a machine busy with other processes
                // (one CI run saw one thread take every block ten times; with
                // 20 ms, none of 8 runs beside three busy loops on two cores did).
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            });
        set_num_threads(threads);
        EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0) << dim << "D";
        EXPECT_EQ(std::memcmp(reported.data(), two.data(), two.size() * sizeof(double)), 0) << dim << "D";
        EXPECT_NE(one, m.points);
        const Method method = variant().method;
        if (dim == 2 && (method == Method::dg_idw || method == Method::idw || method == Method::dg_harmonic)) {
            EXPECT_GE(reporters.size(), 2u) << "the step ran on one thread, ten times";
        }
    }
}

TEST_P(MethodProperties, DeformingInPlaceEqualsDeformingIntoAnotherArray) {
    const BoxInBox m = property_box(3, property_grid(3));
    const Plan plan = prepare_for(m);
    const BoundaryMotion motion = test::random_motion(m, 13, variant().motion_amount);
    const auto out = step(plan, m, motion);
    std::vector<double> in_place = m.points;
    deform(plan, in_place, motion, in_place, variant().options(1.0));
    EXPECT_EQ(in_place, out);
}

TEST_P(MethodProperties, BadStepArraysAreRefusedNamingTheNode) {
    // One check for all methods (check_step_arrays): sizes, and a motion that
    // is not finite, with the node id in the error.
    const BoxInBox m = property_box(2, 12);
    const Plan plan = prepare_for(m);
    std::vector<double> out(m.points.size());
    BoundaryMotion motion(m.boundary.nodes.size());
    EXPECT_THROW(deform(plan, m.points, BoundaryMotion(3), out), MeshError);
    std::vector<double> short_out(out.size() - 2);
    EXPECT_THROW(deform(plan, m.points, motion, short_out), MeshError);
    std::size_t b = 0;
    while (!m.boundary.moving[b]) ++b;
    motion[b].rotation[2] = std::numeric_limits<double>::infinity();
    try {
        deform(plan, m.points, motion, out);
        ADD_FAILURE() << "a non-finite motion was accepted";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("boundary node " + std::to_string(m.boundary.nodes[b])),
                  std::string::npos)
            << e.what();
    }
}

TEST_P(MethodProperties, MotionsBeyondDoubleArithmeticAreRefusedNamingTheNode) {
    // A rotation of 1e300 rad or a translation of 1.7e308 made NaN
    // coordinates (issue #27): refused before the step, by the rule the
    // motion files follow too (motion_value_problem).
    const BoxInBox m = property_box(2, 12);
    const Plan plan = prepare_for(m);
    std::vector<double> out(m.points.size());
    std::size_t b = 0;
    while (!m.boundary.moving[b]) ++b;
    for (const NodeMotion& huge : {NodeMotion{{0, 0, 0}, {0, 0, 1e300}, {0, 0, 0}},
                                  NodeMotion{{1.7e308, 0, 0}, {0, 0, 0}, {0, 0, 0}},
                                  NodeMotion{{1e151, 1e151, 0}, {0, 0, 0}, {0, 0, 0}}}) {
        BoundaryMotion motion(m.boundary.nodes.size());
        motion[b] = huge;
        try {
            deform(plan, m.points, motion, out);
            ADD_FAILURE() << "accepted: translation " << huge.translation[0] << ", rotation " << huge.rotation[2];
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find("boundary node " + std::to_string(m.boundary.nodes[b])),
                      std::string::npos)
                << e.what();
        }
    }
}

TEST_P(MethodProperties, NoNonFiniteCoordinateIsEverReturned) {
    // Whatever makes a coordinate NaN (here a NaN in the points given to the
    // step, at a static boundary node), deform throws, naming a node, instead
    // of returning it (issue #27: the circle centre of the naca0012 case, a
    // node in no cell, became NaN unnoticed).
    const BoxInBox m = property_box(2, 12);
    const Plan plan = prepare_for(m);
    std::size_t b = 0;
    while (m.boundary.moving[b]) ++b;
    std::vector<double> points = m.points;
    points[static_cast<std::size_t>(m.boundary.nodes[b]) * 2] = std::nan("");
    std::vector<double> out(m.points.size());
    try {
        deform(plan, points, BoundaryMotion(m.boundary.nodes.size()), out, variant().options(1.0));
        ADD_FAILURE() << "a NaN coordinate was returned";
    } catch (const InvalidResultError& e) {
        EXPECT_GE(e.count(), 1);
        if (variant().method == Method::dgm) return;  // DGM refuses first: its moved graph is invalid
        EXPECT_NE(std::string(e.what()).find("non-finite new coordinate"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(std::string(method_name(variant().method)) + ": node "), std::string::npos)
            << e.what();
    }
}

TEST(MethodVariants, CoverEveryMethod) {
    for (Method method : all_methods) {
        if (method_needs_cells(method)) continue;  // these are point-set properties; laplacian_test.cpp has its own
        bool found = false;
        for (const MethodVariant& v : method_variants) found = found || v.method == method;
        EXPECT_TRUE(found) << method_name(method);
    }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, MethodProperties, ::testing::ValuesIn(method_variants),
                         [](const ::testing::TestParamInfo<MethodVariant>& info) { return info.param.name; });
