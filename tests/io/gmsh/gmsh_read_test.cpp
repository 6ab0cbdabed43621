#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "io/gmsh/gmsh_test_support.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::vtk_corner_orientation;

namespace {

// 2D, MSH 4.1: sparse node tags, a parametric node block, a point element,
// a curve in two physical groups (one unnamed), a curve in none, a named group
// without elements, and sections to skip.
const char* const square_41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Comments
text that looks like a section: $Nodes
$EndComments
$PhysicalNames
3
1 5 "wall"
1 9 "far field"
2 1 "fluid"
$EndPhysicalNames
$Entities
1 3 1 0
1 0 0 0 0
1 0 0 0 1 0 0 1 5 2 1 -1
2 1 0 0 2 1 0 2 5 7 0
3 1 1 0 2 1 0 0 0
1 0 0 0 2 1 0 1 1 0
$EndEntities
$Nodes
2 6 3 100
0 1 0 1
100
0 0 0
2 1 1 5
7
3
50
12
20
1 0 0 0.5 0.25
1 1 0 0.5 0.5
0 1 0 0.25 0.5
2 0 0 1 0
2 1 0 1 0.5
$EndNodes
$Elements
6 8 1 80
0 1 15 1
80 100
1 1 1 1
2 100 7
1 2 1 2
3 7 12
4 12 20
1 3 1 1
5 20 3
2 1 2 2
10 100 7 3
11 100 3 50
2 1 3 1
12 7 12 20 3
$EndElements
$Periodic
0
$EndPeriodic
)";

// 3D, MSH 2.2: one element of each solid type (each positively oriented in
// Gmsh's order), sparse tags, a cell and a face written twice for two physical
// groups (as Gmsh does), a face without group, a line and a point.
const char* const solids_22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
2 11 "bottom"
3 1 "fluid"
$EndPhysicalNames
$Nodes
23
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
50 0 0 1
60 1 0 1
70 1 1 1
80 0 1 1
101 2 0 0
102 3 0 0
103 2 1 0
104 2 0 1
105 3 0 1
106 2 1 1
201 4 0 0
202 5 0 0
203 5 1 0
204 4 1 0
205 4.5 0.5 1
301 6 0 0
302 7 0 0
303 6 1 0
304 6 0 1
$EndNodes
$Elements
12
1 5 2 1 1 10 20 30 40 50 60 70 80
2 6 2 1 1 101 102 103 104 105 106
3 6 2 2 1 101 102 103 104 105 106
4 7 2 1 1 201 202 203 204 205
5 4 2 1 1 301 302 303 304
6 3 2 11 3 10 40 30 20
7 3 2 12 3 10 40 30 20
8 2 2 11 4 101 103 102
9 2 2 0 5 301 303 302
10 1 2 11 6 10 20
11 15 2 0 7 10
12 2 3 12 8 1 50 60 70
$EndElements
)";

Mesh expected_square() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};  // tags 100, 7, 3, 50, 12, 20
    const NodeId t0[] = {0, 1, 2}, t1[] = {0, 2, 3}, q[] = {1, 4, 5, 2};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    m.cells.push_back(CellType::quadrilateral, q);
    const NodeId e0[] = {0, 1}, e1[] = {1, 4}, e2[] = {4, 5};
    Marker wall{"wall", {}}, seven{"physical_7", {}}, far{"far field", {}};
    wall.elements.push_back(CellType::line, e0);
    wall.elements.push_back(CellType::line, e1);
    wall.elements.push_back(CellType::line, e2);
    seven.elements.push_back(CellType::line, e1);
    seven.elements.push_back(CellType::line, e2);
    m.markers = {wall, seven, far};
    return m;
}

}  // namespace

TEST(GmshRead, Version41SquareWithSparseTagsAndPhysicalGroups) {
    const Mesh m = read_gmsh_text("square.msh", square_41);
    EXPECT_EQ(m, expected_square());
}

TEST(GmshRead, Version22SquareGivesTheSameMesh) {
    // The square of square_41 as Gmsh 2.2 writes it: the line in groups 5 and
    // 7 is repeated, the point and the line in no group are listed too.
    const std::string text = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 5 "wall"
1 9 "far field"
2 1 "fluid"
$EndPhysicalNames
$Nodes
6
100 0 0 0
7 1 0 0
3 1 1 0
50 0 1 0
12 2 0 0
20 2 1 0
$EndNodes
$Elements
10
80 15 2 0 1 100
1 1 2 5 1 100 7
2 1 2 5 2 7 12
3 1 2 7 2 7 12
4 1 2 5 2 12 20
5 1 2 7 2 12 20
6 1 2 0 3 20 3
10 2 2 1 1 100 7 3
11 2 2 1 1 100 3 50
12 3 2 1 1 7 12 20 3
$EndElements
)";
    EXPECT_EQ(read_gmsh_text("square22.msh", text), expected_square());
}

TEST(GmshRead, Version22SolidsAllTypesMergedDuplicatesAndPrismOrder) {
    const Mesh m = read_gmsh_text("solids.msh", solids_22);
    ASSERT_EQ(m.dim, 3);
    ASSERT_EQ(m.num_points(), 23u);
    EXPECT_EQ(m.points[3 * 13 + 0], 2);  // tag 106 is the 14th node: (2, 1, 1)
    EXPECT_EQ(m.points[3 * 13 + 1], 1);
    EXPECT_EQ(m.points[3 * 22 + 2], 1);  // tag 304: (6, 0, 1)

    // The prism written for two groups is one cell.
    ASSERT_EQ(m.cells.size(), 4u);
    EXPECT_EQ(m.cells.types, (std::vector<CellType>{CellType::hexahedron, CellType::prism, CellType::pyramid,
                                                    CellType::tetrahedron}));
    EXPECT_EQ(std::vector<NodeId>(m.cells.nodes_of(0).begin(), m.cells.nodes_of(0).end()),
              (std::vector<NodeId>{0, 1, 2, 3, 4, 5, 6, 7}));
    // Gmsh prism 101..106 = ids 8..13; VTK order swaps nodes 1-2 and 4-5.
    EXPECT_EQ(std::vector<NodeId>(m.cells.nodes_of(1).begin(), m.cells.nodes_of(1).end()),
              (std::vector<NodeId>{8, 10, 9, 11, 13, 12}));
    EXPECT_EQ(std::vector<NodeId>(m.cells.nodes_of(2).begin(), m.cells.nodes_of(2).end()),
              (std::vector<NodeId>{14, 15, 16, 17, 18}));
    // Every cell, positively oriented in Gmsh's order, is positive in VTK's.
    for (std::size_t i = 0; i < m.cells.size(); ++i) EXPECT_GT(vtk_corner_orientation(m, i), 0) << "cell " << i;

    // Markers: tag 11 "bottom", tag 12 unnamed; the quad is in both; the
    // triangle without group, the line and the point are dropped.
    ASSERT_EQ(m.markers.size(), 2u);
    EXPECT_EQ(m.markers[0].name, "bottom");
    EXPECT_EQ(m.markers[1].name, "physical_12");
    EXPECT_EQ(m.markers[0].elements.types, (std::vector<CellType>{CellType::quadrilateral, CellType::triangle}));
    EXPECT_EQ(m.markers[0].elements.nodes, (std::vector<NodeId>{0, 3, 2, 1, 8, 10, 9}));
    EXPECT_EQ(m.markers[1].elements.types, (std::vector<CellType>{CellType::quadrilateral, CellType::triangle}));
    EXPECT_EQ(m.markers[1].elements.nodes, (std::vector<NodeId>{0, 3, 2, 1, 4, 5, 6}));
}

TEST(GmshRead, Version41SolidsMatchVersion22) {
    // solids_22's cells and its bottom/unnamed groups as 4.1 entity blocks,
    // with nodes in two blocks (one parametric in a volume: u v w).
    const std::string text = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
2 11 "bottom"
3 1 "fluid"
$EndPhysicalNames
$Entities
0 1 4 1
1 0 0 0 1 1 0 1 11 0
3 0 0 0 1 1 0 2 12 11 0
4 0 0 0 1 1 0 0 0
5 2 0 0 3 1 0 1 11 0
8 0 0 1 1 1 1 1 12 0
1 0 0 0 7 1 1 1 1 0
$EndEntities
$Nodes
2 23 10 304
3 1 1 3
10
20
30
0 0 0 0 0 0
1 0 0 1 0 0
1 1 0 1 1 0
3 1 0 20
40
50
60
70
80
101
102
103
104
105
106
201
202
203
204
205
301
302
303
304
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
2 0 0
3 0 0
2 1 0
2 0 1
3 0 1
2 1 1
4 0 0
5 0 0
5 1 0
4 1 0
4.5 0.5 1
6 0 0
7 0 0
6 1 0
6 0 1
$EndNodes
$Elements
9 9 1 12
1 1 1 1
10 10 20
2 3 3 1
6 10 40 30 20
2 5 2 1
8 101 103 102
2 4 2 1
9 301 303 302
2 8 2 1
12 50 60 70
3 1 5 1
1 10 20 30 40 50 60 70 80
3 1 6 1
2 101 102 103 104 105 106
3 1 7 1
4 201 202 203 204 205
3 1 4 1
5 301 302 303 304
$EndElements
)";
    test::expect_same_mesh(read_gmsh_text("solids41.msh", text), read_gmsh_text("solids22.msh", solids_22));
}

TEST(GmshRead, Version22NodesAreNumberedInFileOrder) {
    const Mesh m = read_gmsh_text("order.msh",
                                  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n5 0 0 0\n2 1 0 0\n9 0 1 0\n"
                                  "$EndNodes\n$Elements\n1\n1 2 2 0 1 2 9 5\n$EndElements\n");
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.points, (std::vector<double>{0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(m.cells.nodes, (std::vector<NodeId>{1, 2, 0}));
    EXPECT_TRUE(m.markers.empty());
}

TEST(GmshRead, AcceptsWindowsLineEndsAndBlankLines) {
    std::string text;
    for (char c : test::tet_22) {
        if (c == '\n') text += "\r\n";
        else text += c;
    }
    text = "\r\n" + text + "\r\n\r\n";
    EXPECT_EQ(read_gmsh_text("crlf.msh", text), read_gmsh_text("lf.msh", test::tet_22));
}

TEST(GmshRead, SmallVersion22And41FilesAgree) {
    const Mesh a = read_gmsh_text("a.msh", test::tet_22), b = read_gmsh_text("b.msh", test::tet_41);
    EXPECT_EQ(a, b);
    ASSERT_EQ(a.markers.size(), 1u);
    EXPECT_EQ(a.markers[0].name, "physical_5");
    EXPECT_EQ(a.markers[0].elements.nodes, (std::vector<NodeId>{0, 2, 1}));
}

TEST(GmshRead, ReadsFromAFileAndReportsAMissingOne) {
    const auto dir = test::scratch_dir();
    {
        std::ofstream(dir / "tet.msh") << test::tet_41;
    }
    EXPECT_EQ(read_gmsh(dir / "tet.msh"), read_gmsh_text("x", test::tet_41));
    EXPECT_THROW(read_gmsh(dir / "missing.msh"), IoError);
}

// ---- Meshes generated by Gmsh itself (library API), written by gmsh::write. ----

namespace {

namespace geo = gmsh::model::geo;

// Writes the current Gmsh model as MSH `version` (4.1 or 2.2) and reads it back.
Mesh write_with_gmsh_and_read(const std::filesystem::path& file, double version, bool parametric) {
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.SaveParametric", parametric ? 1 : 0);
    gmsh::write(file.string());
    return read_gmsh(file);
}

// The square [x0, x0 + 1] × [0, 1] in the built-in kernel, counter-clockwise;
// returns its surface tag and its 4 curves (bottom, right, top, left).
int add_square(double x0, double size, std::vector<int>& curves) {
    const int p[] = {geo::addPoint(x0, 0, 0, size), geo::addPoint(x0 + 1, 0, 0, size),
                     geo::addPoint(x0 + 1, 1, 0, size), geo::addPoint(x0, 1, 0, size)};
    curves.clear();
    for (int k = 0; k < 4; ++k) curves.push_back(geo::addLine(p[k], p[(k + 1) % 4]));
    return geo::addPlaneSurface({geo::addCurveLoop(curves)});
}

struct Variant {
    double version;
    bool parametric;
};
const Variant variants[] = {{4.1, false}, {4.1, true}, {2.2, false}};

}  // namespace

TEST(GmshLibrary, ReadsAUnitSquareTriangulatedByGmsh) {
    const auto dir = test::scratch_dir();
    test::GmshSession session;
    gmsh::model::add("square");
    std::vector<int> l;
    const int surface = add_square(0, 0.25, l);
    geo::synchronize();
    gmsh::model::addPhysicalGroup(1, {l[0]}, 3);
    gmsh::model::setPhysicalName(1, 3, "bottom");
    gmsh::model::addPhysicalGroup(1, {l[1], l[3]}, 1);
    gmsh::model::setPhysicalName(1, 1, "sides");
    gmsh::model::addPhysicalGroup(1, {l[2]}, 8);  // unnamed
    gmsh::model::addPhysicalGroup(2, {surface}, 2);
    gmsh::model::setPhysicalName(2, 2, "fluid");
    gmsh::model::mesh::generate(2);

    const std::size_t nodes = test::gmsh_node_count();
    const auto cells = test::gmsh_element_counts(2);
    ASSERT_EQ(cells.size(), 1u);
    ASSERT_GT(cells.at(2), 8u);  // triangles only
    const std::size_t sides = test::gmsh_group_size(1, 1), bottom = test::gmsh_group_size(1, 3),
                      top = test::gmsh_group_size(1, 8);

    for (const Variant& v : variants) {
        SCOPED_TRACE(testing::Message() << "MSH " << v.version << (v.parametric ? " parametric" : ""));
        const Mesh m = write_with_gmsh_and_read(dir / "square.msh", v.version, v.parametric);
        EXPECT_EQ(m.dim, 2);
        EXPECT_EQ(m.num_points(), nodes);
        EXPECT_EQ(m.cells.size(), cells.at(2));
        ASSERT_EQ(m.markers.size(), 3u);  // in tag order 1, 3, 8
        EXPECT_EQ(m.markers[0].name, "sides");
        EXPECT_EQ(m.markers[1].name, "bottom");
        EXPECT_EQ(m.markers[2].name, "physical_8");
        EXPECT_EQ(m.markers[0].elements.size(), sides);
        EXPECT_EQ(m.markers[1].elements.size(), bottom);
        EXPECT_EQ(m.markers[2].elements.size(), top);
        double area = 0;
        for (std::size_t i = 0; i < m.cells.size(); ++i) {
            ASSERT_EQ(m.cells.types[i], CellType::triangle);
            const double a = vtk_corner_orientation(m, i);
            EXPECT_GT(a, 0) << "triangle " << i << " is clockwise";
            area += a / 2;
        }
        EXPECT_NEAR(area, 1.0, 1e-12);
    }
}

TEST(GmshLibrary, ReadsATetrahedralBoxMeshedByGmsh) {
    const auto dir = test::scratch_dir();
    test::GmshSession session;
    gmsh::model::add("box");
    std::vector<int> l;
    const int bottom = add_square(0, 0.5, l);
    gmsh::vectorpair out;  // top surface, volume, 4 side surfaces
    geo::extrude({{2, bottom}}, 0, 0, 1, out);
    geo::synchronize();
    ASSERT_EQ(out.size(), 6u);
    gmsh::model::addPhysicalGroup(2, {bottom}, 1);
    gmsh::model::setPhysicalName(2, 1, "bottom");
    gmsh::model::addPhysicalGroup(2, {out[0].second}, 2);
    gmsh::model::setPhysicalName(2, 2, "top");
    gmsh::model::addPhysicalGroup(2, {out[2].second, out[3].second, out[4].second, out[5].second}, 5);
    gmsh::model::addPhysicalGroup(2, {bottom, out[0].second}, 6);  // faces in two groups
    gmsh::model::setPhysicalName(2, 6, "bottom and top");
    // The volume in two groups too: MSH 2.2 then lists every tetrahedron twice.
    gmsh::model::addPhysicalGroup(3, {out[1].second}, 4);
    gmsh::model::setPhysicalName(3, 4, "fluid");
    gmsh::model::addPhysicalGroup(3, {out[1].second}, 7);
    gmsh::model::mesh::generate(3);

    const std::size_t nodes = test::gmsh_node_count();
    const auto cells = test::gmsh_element_counts(3);
    ASSERT_EQ(cells.size(), 1u);
    ASSERT_GT(cells.at(4), 6u);  // tetrahedra only

    for (const Variant& v : variants) {
        SCOPED_TRACE(testing::Message() << "MSH " << v.version << (v.parametric ? " parametric" : ""));
        const Mesh m = write_with_gmsh_and_read(dir / "box.msh", v.version, v.parametric);
        EXPECT_EQ(m.dim, 3);
        EXPECT_EQ(m.num_points(), nodes);
        EXPECT_EQ(m.cells.size(), cells.at(4));
        ASSERT_EQ(m.markers.size(), 4u);
        EXPECT_EQ(m.markers[0].name, "bottom");
        EXPECT_EQ(m.markers[1].name, "top");
        EXPECT_EQ(m.markers[2].name, "physical_5");
        EXPECT_EQ(m.markers[3].name, "bottom and top");
        EXPECT_EQ(m.markers[0].elements.size(), test::gmsh_group_size(2, 1));
        EXPECT_EQ(m.markers[1].elements.size(), test::gmsh_group_size(2, 2));
        EXPECT_EQ(m.markers[2].elements.size(), test::gmsh_group_size(2, 5));
        EXPECT_EQ(m.markers[3].elements.size(), m.markers[0].elements.size() + m.markers[1].elements.size());
        double volume = 0;
        for (std::size_t i = 0; i < m.cells.size(); ++i) {
            ASSERT_EQ(m.cells.types[i], CellType::tetrahedron);
            const double six_v = vtk_corner_orientation(m, i);
            EXPECT_GT(six_v, 0) << "tetrahedron " << i << " is inverted";
            volume += six_v / 6;
        }
        EXPECT_NEAR(volume, 1.0, 1e-12);
    }
}

TEST(GmshLibrary, ExtrudedPrismsAndHexahedraKeepVtkOrientation) {
    const auto dir = test::scratch_dir();
    test::GmshSession session;
    gmsh::model::add("layers");
    std::vector<int> la, lb;
    const int triangles = add_square(0, 0.5, la);
    const int quads = add_square(2, 0.5, lb);
    for (int c : lb) geo::mesh::setTransfiniteCurve(c, 3);
    geo::mesh::setTransfiniteSurface(quads);
    geo::mesh::setRecombine(2, quads);
    gmsh::vectorpair out_a, out_b;
    geo::extrude({{2, triangles}}, 0, 0, 1, out_a, {2}, {}, true);
    geo::extrude({{2, quads}}, 0, 0, 1, out_b, {2}, {}, true);
    geo::synchronize();
    gmsh::model::addPhysicalGroup(2, {triangles, quads}, 1);
    gmsh::model::setPhysicalName(2, 1, "bottom");
    gmsh::model::addPhysicalGroup(3, {out_a[1].second, out_b[1].second}, 2);
    gmsh::model::mesh::generate(3);

    const auto cells = test::gmsh_element_counts(3);
    ASSERT_EQ(cells.size(), 2u);
    const std::size_t prisms = cells.at(6), hexes = cells.at(5);
    EXPECT_EQ(hexes, 8u);  // 2 × 2 quads, 2 layers

    for (const Variant& v : variants) {
        SCOPED_TRACE(testing::Message() << "MSH " << v.version << (v.parametric ? " parametric" : ""));
        const Mesh m = write_with_gmsh_and_read(dir / "layers.msh", v.version, v.parametric);
        const auto counts = test::cell_type_map(m.cells);
        EXPECT_EQ(counts.at(CellType::prism), prisms);
        EXPECT_EQ(counts.at(CellType::hexahedron), hexes);
        ASSERT_EQ(m.markers.size(), 1u);
        EXPECT_EQ(m.markers[0].elements.size(), test::gmsh_group_size(2, 1));
        for (std::size_t i = 0; i < m.cells.size(); ++i)
            EXPECT_GT(vtk_corner_orientation(m, i), 0)
                << cell_type_name(m.cells.types[i]) << " " << i << " is inverted in VTK order";
    }
}
