#include "dgwarp/mesh/mesh_counts.hpp"

#include <gtest/gtest.h>

using namespace dgwarp;

TEST(MeshCounts, NodesCellsByTypeAndMarkersCountedByHand) {
    // Two triangles and a quad over six nodes; a wall of three edges (one
    // given twice) over three nodes, and an inlet of one edge.
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
    const NodeId t0[] = {0, 1, 4}, t1[] = {0, 4, 3}, q[] = {1, 2, 5, 4};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    m.cells.push_back(CellType::quadrilateral, q);
    Marker wall{"wall", {}}, inlet{"inlet", {}};
    const NodeId e0[] = {0, 1}, e1[] = {1, 2}, e2[] = {2, 1}, e3[] = {0, 3};
    wall.elements.push_back(CellType::line, e0);
    wall.elements.push_back(CellType::line, e1);
    wall.elements.push_back(CellType::line, e2);
    inlet.elements.push_back(CellType::line, e3);
    m.markers = {wall, inlet};

    const MeshCounts c = mesh_counts(m);
    EXPECT_EQ(c.dim, 2);
    EXPECT_EQ(c.nodes, 6);
    EXPECT_EQ(c.cells, 3);
    ASSERT_EQ(c.cell_types.size(), std::size(all_cell_types));
    EXPECT_EQ(c.cell_types[static_cast<std::size_t>(CellType::triangle)], 2);
    EXPECT_EQ(c.cell_types[static_cast<std::size_t>(CellType::quadrilateral)], 1);
    EXPECT_EQ(c.cell_types[static_cast<std::size_t>(CellType::tetrahedron)], 0);
    ASSERT_EQ(c.markers.size(), 2u);
    EXPECT_EQ(c.markers[0].name, "wall");
    EXPECT_EQ(c.markers[0].elements, 3);
    EXPECT_EQ(c.markers[0].nodes, 3);  // 0, 1, 2: each once
    EXPECT_EQ(c.markers[1].name, "inlet");
    EXPECT_EQ(c.markers[1].elements, 1);
    EXPECT_EQ(c.markers[1].nodes, 2);
}
