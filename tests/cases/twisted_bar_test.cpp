#include "dgwarp/cases/twisted_bar.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

TEST(CasesTwistedBar, HasThePapersCountsAndIdealCells) {
    const Mesh m = make_twisted_bar();
    EXPECT_EQ(m.num_points(), 7520u);
    EXPECT_EQ(m.cells.size(), 7308u);
    EXPECT_NO_THROW(validate(m));
    const QualitySummary q = summarize_quality(cell_qualities(m, std::vector<std::int8_t>(m.cells.size(), 1)));
    EXPECT_NEAR(q.min, 1.0, 1e-12);
    EXPECT_TRUE(make_twisted_bar() == m);
}

TEST(CasesTwistedBar, BarMarkerIsTheCentredBar) {
    const Mesh m = make_twisted_bar();
    const double h = 20.0 / 87;
    const auto bar = marker_nodes(find_marker(m, "bar"));
    EXPECT_EQ(bar.size(), 2u * (29 + 9));
    for (NodeId n : bar)
        EXPECT_NEAR(std::max(std::abs(m.points[2 * n]) / (14.5 * h), std::abs(m.points[2 * n + 1]) / (4.5 * h)), 1.0,
                    1e-12);
    EXPECT_EQ(marker_nodes(find_marker(m, "farfield")).size(), 4u * 87);
}
