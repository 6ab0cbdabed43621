// The core the graph methods' plans share (methods/plan_core.hpp): the
// boundary set they were built for, each boundary node marked -1 - b in
// node_simplex and every volume node in a simplex of the plan's graph, and
// its bytes counted in the plan's.
#include "dgwarp/methods/plan_core.hpp"

#include <gtest/gtest.h>

#include "dgwarp/methods/method.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;

TEST(PlanCore, TheGraphPlansHoldTheBoundarySetAndLocateEveryNode) {
    for (int dim : {2, 3}) {
        const test::BoxInBox m = test::box_in_box(dim, dim == 2 ? 12 : 6);
        for (Method method : {Method::dg_idw, Method::dgm, Method::dg_harmonic}) {
            SCOPED_TRACE(std::string(method_name(method)) + " " + std::to_string(dim) + "D");
            const Plan plan = prepare(method, dim, m.points, m.boundary);
            ASSERT_NE(graph_plan_core(plan), nullptr);
            const GraphPlanCore& core = *graph_plan_core(plan);
            EXPECT_EQ(core.dim, dim);
            EXPECT_EQ(core.boundary_nodes, m.boundary.nodes);
            EXPECT_EQ(core.boundary_moving, m.boundary.moving);
            ASSERT_EQ(core.num_points(), m.num_points());
            EXPECT_EQ(core.num_volume_nodes(), m.num_points() - static_cast<std::int64_t>(m.boundary.nodes.size()));
            for (std::size_t b = 0; b < core.boundary_nodes.size(); ++b)
                EXPECT_EQ(core.node_simplex[static_cast<std::size_t>(core.boundary_nodes[b])], -1 - static_cast<int>(b));
            std::int64_t located = 0;
            for (std::int32_t s : core.node_simplex) located += s >= 0;
            EXPECT_EQ(located, core.num_volume_nodes());
            // No coincident boundary nodes: no shared vertex, and nothing to conflict.
            EXPECT_EQ(core.shared_offsets, std::vector<std::int32_t>{0});
            EXPECT_EQ(conflicting_shared_vertices(core, BoundaryMotion(core.boundary_nodes.size())), 0);
            EXPECT_GT(core_bytes(core), 0u);
            EXPECT_LT(core_bytes(core), plan_memory_bytes(plan));
        }
        // The other methods' plans have no graph core.
        EXPECT_EQ(graph_plan_core(prepare(Method::idw, dim, m.points, m.boundary)), nullptr);
        EXPECT_EQ(graph_plan_core(prepare(Method::rbf, dim, m.points, m.boundary)), nullptr);
    }
}
