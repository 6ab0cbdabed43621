// The common interface: every method is reachable by name, and plan
// summaries mean the same for every method. (What every method does through
// the interface: method_properties_test.cpp.)
#include "dgwarp/methods/method.hpp"

#include <gtest/gtest.h>

#include "dgwarp/plan/plan_file.hpp"
#include "support/box_in_box.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

TEST(Method, NamesRoundTrip) {
    for (Method m : all_methods) {
        const auto back = method_from_name(method_name(m));
        ASSERT_TRUE(back.has_value()) << method_name(m);
        EXPECT_EQ(*back, m);
    }
    EXPECT_FALSE(method_from_name("spring").has_value());
}

TEST(Method, PlanSummariesCountTheSameGraphAlikeForEveryMethod) {
    // DG-IDW and DGM build the same Delaunay graph and locate the same nodes
    // in it: the same whole graph and the same simplices holding a volume
    // node (the simplices inside the inner box hold none). A DG-IDW plan keeps
    // only the latter, so once saved and loaded it no longer knows the former.
    for (int dim : {2, 3}) {
        const test::BoxInBox m = test::box_in_box(dim, dim == 2 ? 12 : 6);
        const PlanSummary dg_idw = plan_summary(prepare(Method::dg_idw, dim, m.points, m.boundary));
        const PlanSummary dgm = plan_summary(prepare(Method::dgm, dim, m.points, m.boundary));
        ASSERT_TRUE(dg_idw.graph_simplices.has_value());
        EXPECT_EQ(dg_idw.graph_simplices, dgm.graph_simplices) << dim << "D";
        EXPECT_EQ(dg_idw.graph_simplices_used, dgm.graph_simplices_used) << dim << "D";
        EXPECT_GT(dgm.graph_simplices_used, 0);
        EXPECT_LT(dgm.graph_simplices_used, *dgm.graph_simplices) << dim << "D";

        const auto file = test::scratch_dir() / "plan";
        save_plan(file, prepare(Method::dg_idw, dim, m.points, m.boundary));
        const PlanSummary loaded = plan_summary(load_plan(file));
        EXPECT_FALSE(loaded.graph_simplices.has_value());
        EXPECT_EQ(loaded.graph_simplices_used, dg_idw.graph_simplices_used);

        const PlanSummary idw = plan_summary(prepare(Method::idw, dim, m.points, m.boundary));
        EXPECT_EQ(idw.graph_simplices, 0);
        EXPECT_EQ(idw.graph_simplices_used, 0);
    }
}
