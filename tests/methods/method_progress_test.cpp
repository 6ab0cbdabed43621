// prepare and deform report their progress through the one interface, per
// block of nodes where they take long, and a callback changes no bit of the
// result (here on two threads against one without it).
#include <gtest/gtest.h>

#include <cstring>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/method.hpp"
#include "support/box_in_box.hpp"
#include "support/progress_recorder.hpp"

using namespace dgwarp;

namespace {

// The inner box turned and moved.
BoundaryMotion turn(const test::BoxInBox& m) {
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b)
        if (m.boundary.moving[b]) motion[b] = {{0.01, -0.02, 0}, {0, 0, 0.1}, m.inner_center};
    return motion;
}

struct Case {
    const char* name;
    Method method;
    MethodOptions options;
    std::size_t min_prepare_calls;  // what a per-block report gives at least
    std::size_t min_deform_calls;
};

std::vector<Case> cases() {
    // DG-IDW and DG-harmonic: 0, a block of 16384 nodes, 1 (issue #27, item 11: only the end before).
    std::vector<Case> c = {{"dg-idw", Method::dg_idw, {}, 5, 3},
                           {"dg-harmonic", Method::dg_harmonic, {}, 1, 3},
                           {"dgm", Method::dgm, {}, 5, 1},
                           {"idw", Method::idw, {}, 1, 8},
                           {"rbf dense", Method::rbf, {}, 50, 8},
                           {"rbf sparse", Method::rbf, {}, 50, 8}};
    c.back().options.rbf.support_radius = 0.3;
    return c;
}

}  // namespace

TEST(MethodProgress, PrepareAndDeformReportAndChangeNoBit) {
    const test::BoxInBox m = test::box_in_box(2, 150);
    ASSERT_GT(m.volume.size(), 2u * 8192u);
    const BoundaryMotion motion = turn(m);
    const int threads = num_threads();
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        set_num_threads(1);
        const Plan plain_plan = prepare(c.method, m.dim, m.points, m.boundary, c.options);
        std::vector<double> plain(m.points.size());
        deform(plain_plan, m.points, motion, plain, c.options);

        set_num_threads(2);
        test::ProgressRecorder prepared, deformed;
        const Plan plan = prepare(c.method, m.dim, m.points, m.boundary, c.options, prepared.fn());
        std::vector<double> out(m.points.size());
        deform(plan, m.points, motion, out, c.options, deformed.fn());
        set_num_threads(threads);

        prepared.expect_complete(c.min_prepare_calls);
        deformed.expect_complete(c.min_deform_calls);
        EXPECT_EQ(std::memcmp(plain.data(), out.data(), out.size() * sizeof(double)), 0);
    }
}
