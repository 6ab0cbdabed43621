#include "dgwarp/mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

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

// ---- polygons and polyhedra ------------------------------------------------

namespace {

/// Two unit cubes side by side (x in [0,2]) as two polyhedra, faces outward,
/// the shared face x = 1 once each way; markers: the left face, a polygon.
Mesh two_cube_polyhedra() {
    Mesh m;
    m.dim = 3;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i) m.points.insert(m.points.end(), {double(i), double(j), double(k)});
    const auto id = [](int i, int j, int k) { return static_cast<NodeId>(i + 3 * j + 6 * k); };
    for (int c = 0; c < 2; ++c) {
        const NodeId n[8] = {id(c, 0, 0), id(c + 1, 0, 0), id(c + 1, 1, 0), id(c, 1, 0),
                             id(c, 0, 1), id(c + 1, 0, 1), id(c + 1, 1, 1), id(c, 1, 1)};
        const std::vector<NodeId> rings{n[0], n[3], n[2], n[1], n[4], n[5], n[6], n[7], n[0], n[1], n[5], n[4],
                                        n[1], n[2], n[6], n[5], n[2], n[3], n[7], n[6], n[3], n[0], n[4], n[7]};
        m.cells.push_polyhedron(rings, std::vector<int>(6, 4));
    }
    Marker left{"left", {}};
    left.elements.push_back(CellType::polygon, std::array<NodeId, 4>{id(0, 0, 0), id(0, 0, 1), id(0, 1, 1), id(0, 1, 0)});
    m.markers.push_back(left);
    return m;
}

}  // namespace

TEST(MeshPolyhedra, PushKeepsFacesAndDistinctNodesInFirstSeenOrder) {
    const Mesh m = two_cube_polyhedra();
    ASSERT_EQ(m.cells.size(), 2u);
    EXPECT_TRUE(m.cells.has_faces());
    EXPECT_EQ(m.cells.types[1], CellType::polyhedron);
    const auto nodes = m.cells.nodes_of(0);
    EXPECT_EQ(std::vector<NodeId>(nodes.begin(), nodes.end()), (std::vector<NodeId>{0, 3, 4, 1, 6, 7, 10, 9}));
    const auto [f0, f1] = m.cells.faces_of(1);
    EXPECT_EQ(f0, 6);
    EXPECT_EQ(f1, 12);
    const auto ring = m.cells.face_nodes_of(7);  // cell 1's top face
    EXPECT_EQ(std::vector<NodeId>(ring.begin(), ring.end()), (std::vector<NodeId>{7, 8, 11, 10}));
    EXPECT_NO_THROW(validate(m));
    // A fixed-type element after a polyhedron keeps the face index in step.
    Mesh more = m;
    more.cells.push_back(CellType::tetrahedron, std::array<NodeId, 4>{0, 1, 3, 6});
    EXPECT_EQ(more.cells.faces_of(2).first, more.cells.faces_of(2).second);
    EXPECT_NO_THROW(validate(more));
    // copy_element and for_each_node_id carry the faces.
    ElementList copy;
    copy_element(m.cells, 1, copy);
    EXPECT_EQ(copy.face_nodes, std::vector<NodeId>(m.cells.face_nodes.begin() + 24, m.cells.face_nodes.end()));
    for_each_node_id(copy, [](NodeId& n) { n += 100; });
    EXPECT_EQ(copy.face_nodes_of(1)[0], 107);
    EXPECT_EQ(copy.nodes_of(0)[0], 101);
}

TEST(MeshPolyhedra, ValidateNamesBadPolyhedraAndPolygons) {
    {
        Mesh m = two_cube_polyhedra();
        m.cells.face_nodes[5] = 2;  // a face of cell 0 names a node not among its 8
        try {
            validate(m);
            FAIL();
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find("cell element 0 (polyhedron): a face names node 2"), std::string::npos)
                << e.what();
        }
    }
    {
        Mesh m = two_cube_polyhedra();
        ElementList three;  // 3 faces only
        three.push_polyhedron(std::vector<NodeId>{0, 1, 3, 0, 3, 6, 0, 6, 1}, std::vector<int>{3, 3, 3});
        m.cells = three;
        EXPECT_THROW(validate(m), MeshError);
    }
    {
        Mesh m = two_cube_polyhedra();
        m.markers[0].elements.push_back(CellType::polygon, std::array<NodeId, 3>{0, 1, 2});
        m.markers[0].elements.offsets.back() -= 1;  // a polygon of 2 nodes
        m.markers[0].elements.nodes.pop_back();
        EXPECT_THROW(validate(m), MeshError);
    }
    // Formats without polygons or polyhedra say which element and where to go.
    try {
        check_fixed_cell_types(two_cube_polyhedra(), "SU2");
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cell 0 is a polyhedron, which SU2 files cannot hold (write .vtu, .cgns or an OpenFOAM case)");
    }
}
