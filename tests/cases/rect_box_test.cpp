#include "dgwarp/cases/rect_box.hpp"

#include <gtest/gtest.h>

#include "support/cell_area.hpp"

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

using dgwarp::test::signed_area;

TEST(CasesRectBox, HasThePapersNodeCountAndValidCells) {
    const Mesh m = make_rect_box();
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.num_points(), 2340u);
    EXPECT_EQ(m.cells.size(), 78u * 29u);
    EXPECT_NO_THROW(validate(m));
    double total = 0;
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        ASSERT_GT(signed_area(m, c), 0) << "cell " << c;
        total += signed_area(m, c);
    }
    // The cells tile the box minus the rectangle exactly.
    EXPECT_NEAR(total, 40.0 * 40.0 - 2.0 * 1.0, 1e-9);
}

TEST(CasesRectBox, MarkersHoldTheRectangleAndTheBox) {
    const Mesh m = make_rect_box();
    const auto rect = marker_nodes(find_marker(m, "rectangle"));
    const auto far = marker_nodes(find_marker(m, "farfield"));
    EXPECT_EQ(rect.size(), 78u);
    EXPECT_EQ(far.size(), 78u);
    for (NodeId n : rect) {
        const double x = m.points[2 * n], y = m.points[2 * n + 1];
        EXPECT_NEAR(std::max(std::abs(x) / 1.0, std::abs(y) / 0.5), 1.0, 1e-12);
    }
    for (NodeId n : far) EXPECT_NEAR(std::max(std::abs(m.points[2 * n]), std::abs(m.points[2 * n + 1])), 20.0, 1e-12);
}

TEST(CasesRectBox, RejectsCornersOffTheNodes) {
    RectBoxOptions o;
    o.around = 77;
    EXPECT_THROW(make_rect_box(o), MeshError);
}
