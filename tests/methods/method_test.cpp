// The common interface: every method is reachable by name and behaves like
// its own functions.
#include "dgwarp/methods/method.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "dgwarp/core/error.hpp"

#include "support/box_in_box.hpp"

using namespace dgwarp;

TEST(Method, NamesRoundTrip) {
    for (Method m : all_methods) {
        const auto back = method_from_name(method_name(m));
        ASSERT_TRUE(back.has_value()) << method_name(m);
        EXPECT_EQ(*back, m);
    }
    EXPECT_FALSE(method_from_name("spring").has_value());
}

TEST(Method, EveryMethodFollowsTheBoundaryAndKeepsZeroMotionTheIdentity) {
    const auto m = test::box_in_box(2, 12);
    for (Method method : all_methods) {
        SCOPED_TRACE(std::string(method_name(method)));
        const Plan plan = prepare(method, m.dim, m.points, m.boundary);
        EXPECT_EQ(plan_method(plan), method);
        EXPECT_GT(plan_memory_bytes(plan), 0u);
        std::vector<double> out(m.points.size());
        deform(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), out);
        EXPECT_EQ(out, m.points);

        BoundaryMotion motion(m.boundary.nodes.size());
        for (std::size_t b = 0; b < motion.size(); ++b)
            if (m.boundary.moving[b]) motion[b].translation = {0.01, -0.02, 0};
        deform(plan, m.points, motion, out);
        for (std::size_t b = 0; b < motion.size(); ++b) {
            const NodeId n = m.boundary.nodes[b];
            double expected[2];
            apply_motion(motion[b], std::span(m.points).subspan(2 * n, 2), expected);
            EXPECT_NEAR(out[2 * n], expected[0], 1e-12);
            EXPECT_NEAR(out[2 * n + 1], expected[1], 1e-12);
        }
    }
}

TEST(Method, EveryMethodRefusesBadStepArraysNamingTheNode) {
    // One check for all methods (check_step_arrays): sizes, and a motion that
    // is not finite, with the node id in the error.
    const auto m = test::box_in_box(2, 12);
    for (Method method : all_methods) {
        SCOPED_TRACE(std::string(method_name(method)));
        const Plan plan = prepare(method, m.dim, m.points, m.boundary);
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
}
