#include "dgwarp/mesh/mesh.hpp"

#include <gtest/gtest.h>

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

namespace {
Mesh unit_square_two_triangles() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 1, 1, 0, 1};
    const NodeId t0[] = {0, 1, 2}, t1[] = {0, 2, 3};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    Marker wall{"wall", {}};
    const NodeId e0[] = {0, 1}, e1[] = {1, 2};
    wall.elements.push_back(CellType::line, e0);
    wall.elements.push_back(CellType::line, e1);
    m.markers.push_back(wall);
    return m;
}
}  // namespace

TEST(Mesh, CountsAndElementAccess) {
    const Mesh m = unit_square_two_triangles();
    EXPECT_EQ(m.num_points(), 4u);
    ASSERT_EQ(m.cells.size(), 2u);
    EXPECT_EQ(m.cells.nodes_of(1)[2], 3);
    EXPECT_NO_THROW(validate(m));
}

TEST(Mesh, MarkerNodesAreSortedAndUnique) {
    const Mesh m = unit_square_two_triangles();
    EXPECT_EQ(marker_nodes(m.markers[0]), (std::vector<NodeId>{0, 1, 2}));
}

TEST(Mesh, FindMarkerNamesTheUnknownOneAndTheKnownOnes) {
    const Mesh m = unit_square_two_triangles();
    EXPECT_EQ(&find_marker(m, "wall"), &m.markers[0]);
    try {
        find_marker(m, "airfoil");
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "airfoil");
        EXPECT_NE(std::string(e.what()).find("wall"), std::string::npos);
    }
}

TEST(Mesh, ValidateRejectsNodeOutOfRange) {
    Mesh m = unit_square_two_triangles();
    m.cells.nodes[4] = 1000000000;
    try {
        validate(m);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_EQ(e.index(), 1);
        EXPECT_NE(std::string(e.what()).find("1000000000"), std::string::npos);
    }
}

TEST(Mesh, ValidateRejectsCellOfWrongDimension) {
    Mesh m = unit_square_two_triangles();
    const NodeId tet[] = {0, 1, 2, 3};
    m.cells.push_back(CellType::tetrahedron, tet);
    EXPECT_THROW(validate(m), MeshError);
}

TEST(Mesh, ValidateRejectsTwoMarkersOfOneName) {
    // A motion names markers: both would move (issue #27, Gmsh physical groups).
    Mesh m = unit_square_two_triangles();
    m.markers.push_back(m.markers[0]);
    try {
        validate(m);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "wall");
        EXPECT_NE(std::string(e.what()).find("markers 1 and 2"), std::string::npos) << e.what();
    }
    m.markers[1].name = "wall2";
    EXPECT_NO_THROW(validate(m));
}

TEST(Mesh, ValidateRejectsAMeshWithoutCells) {
    // Issue #27: a 0-cell SU2 mesh was read, "measured" (min quality 0 of
    // cell -1), deformed and written to files the readers then refused.
    Mesh m = unit_square_two_triangles();
    m.cells = {};
    try {
        validate(m);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("no cells"), std::string::npos) << e.what();
    }
}

TEST(Mesh, APointCloudHasNoCellsAndMarkersOfNodes) {
    Mesh m = unit_square_two_triangles();
    m.cells = {};
    m.markers.clear();
    const NodeId corner = 0, far = 2;
    m.markers.push_back({"a", {}});
    m.markers.back().elements.push_back(CellType::vertex, std::span<const NodeId>(&corner, 1));
    if (m.dim == 2) m.markers.back().elements.push_back(CellType::line, std::vector<NodeId>{1, 2});
    EXPECT_NO_THROW(validate_point_cloud(m));
    EXPECT_THROW(validate(m), MeshError);  // a mesh needs cells
    m.dim = 3;  // vertex markers in 3D too
    m.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    m.markers.back().elements = {};
    m.markers.back().elements.push_back(CellType::vertex, std::span<const NodeId>(&far, 1));
    EXPECT_NO_THROW(validate_point_cloud(m));
    const NodeId out_of_range = 4;
    m.markers.back().elements.push_back(CellType::vertex, std::span<const NodeId>(&out_of_range, 1));
    EXPECT_THROW(validate_point_cloud(m), MeshError);
    Mesh with_cells = unit_square_two_triangles();
    EXPECT_THROW(validate_point_cloud(with_cells), MeshError);  // a cloud has none
}

TEST(Mesh, BoundingBoxAndTypeCounts) {
    Mesh m = unit_square_two_triangles();
    m.points[2] = 3.5;   // node 1 x
    m.points[7] = -2.0;  // node 3 y
    const BoundingBox box = bounding_box(m);
    EXPECT_EQ(box.min[0], 0.0);
    EXPECT_EQ(box.max[0], 3.5);
    EXPECT_EQ(box.min[1], -2.0);
    EXPECT_EQ(box.max[1], 1.0);
    const auto counts = count_by_type(m.cells);
    EXPECT_EQ(counts[static_cast<int>(CellType::triangle)], 2);
    EXPECT_EQ(counts[static_cast<int>(CellType::quadrilateral)], 0);
}
