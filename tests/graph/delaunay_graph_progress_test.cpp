// build_located_graph reports per located block, and the callback changes
// nothing in the graph or the location.
#include <gtest/gtest.h>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "support/box_in_box.hpp"
#include "support/progress_recorder.hpp"

using namespace dgwarp;

TEST(GraphProgress, ReportsPerLocatedBlockAndChangesNothing) {
    for (int dim : {2, 3}) {
        SCOPED_TRACE(dim);
        // Several location blocks of 8192 queries.
        const test::BoxInBox m = test::box_in_box(dim, dim == 2 ? 200 : 36);
        ASSERT_GT(m.volume.size(), 3u * 8192u);
        const int threads = num_threads();
        set_num_threads(1);
        const LocatedGraph plain = build_located_graph(dim, m.points, m.boundary.nodes, m.volume);
        set_num_threads(2);
        test::ProgressRecorder rec;
        const LocatedGraph reported = build_located_graph(dim, m.points, m.boundary.nodes, m.volume, {}, rec.fn());
        set_num_threads(threads);
        // 0, the triangulation's share, one per block, 1.
        rec.expect_complete(2 + m.volume.size() / 8192);
        EXPECT_EQ(rec.fractions().front(), 0.0);
        EXPECT_EQ(plain.graph.simplices, reported.graph.simplices);
        EXPECT_EQ(plain.location.simplex, reported.location.simplex);
        EXPECT_EQ(plain.location.outside_count, reported.location.outside_count);
    }
}
