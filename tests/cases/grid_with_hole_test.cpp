#include "dgwarp/cases/grid_with_hole.hpp"

#include <gtest/gtest.h>

#include "support/cell_area.hpp"

#include <cmath>

#include "dgwarp/core/error.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

using dgwarp::test::signed_area;

TEST(CasesGridWithHole, HasThePapersNodeCountAndIdealCells) {
    const Mesh m = make_grid_with_hole();
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.num_points(), 2340u);
    EXPECT_EQ(m.cells.size(), 49u * 49u - 21u * 9u);
    EXPECT_NO_THROW(validate(m));
    const double h = 20.0 / 49;
    double total = 0;
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        ASSERT_NEAR(signed_area(m, c), h * h, 1e-12) << "cell " << c;
        total += signed_area(m, c);
    }
    // The cells tile the box minus the rectangle exactly.
    EXPECT_NEAR(total, 20.0 * 20.0 - (21 * h) * (9 * h), 1e-9);
    const QualitySummary q = summarize_quality(cell_qualities(m, cell_orientations(m)));
    EXPECT_NEAR(q.min, 1.0, 1e-12);
}

TEST(CasesGridWithHole, MarkersAreClosedLoopsOnTheRectangleAndTheBox) {
    const Mesh m = make_grid_with_hole();
    const double h = 20.0 / 49;
    const auto& rect = find_marker(m, "rectangle");
    const auto& far = find_marker(m, "farfield");
    EXPECT_EQ(rect.elements.size(), 2u * (21 + 9));
    EXPECT_EQ(far.elements.size(), 4u * 49);
    EXPECT_EQ(marker_nodes(rect).size(), rect.elements.size());  // a closed loop
    for (NodeId n : marker_nodes(rect)) {
        const double x = m.points[2 * n], y = m.points[2 * n + 1];
        EXPECT_NEAR(std::max(std::abs(x) / (10.5 * h), std::abs(y) / (4.5 * h)), 1.0, 1e-12);
    }
    for (NodeId n : marker_nodes(far))
        EXPECT_NEAR(std::max(std::abs(m.points[2 * n]), std::abs(m.points[2 * n + 1])), 10.0, 1e-12);
    // Each loop runs counter-clockwise: positive signed area of the polygon.
    double area = 0;
    for (std::size_t e = 0; e < rect.elements.size(); ++e) {
        const auto n = rect.elements.nodes_of(e);
        area += m.points[2 * n[0]] * m.points[2 * n[1] + 1] - m.points[2 * n[1]] * m.points[2 * n[0] + 1];
    }
    EXPECT_NEAR(area / 2, (21 * h) * (9 * h), 1e-9);
}

TEST(CasesGridWithHole, RejectsARectangleOffTheGridLines) {
    GridWithHoleOptions o;
    o.rect_cells_x = 20;
    EXPECT_THROW(make_grid_with_hole(o), MeshError);
    o.rect_cells_x = 49;
    EXPECT_THROW(make_grid_with_hole(o), MeshError);
}
