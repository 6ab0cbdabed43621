#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh.hpp"
#include "io/gmsh_test_support.hpp"
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

// The line numbers of `text` (1-based) replaced or removed.
std::string edit_lines(const std::string& text, std::vector<std::pair<int, std::optional<std::string>>> edits) {
    std::istringstream in(text);
    std::string line, out;
    for (int n = 1; std::getline(in, line); ++n) {
        bool removed = false;
        for (const auto& [k, replacement] : edits)
            if (k == n) {
                if (replacement)
                    line = *replacement;
                else
                    removed = true;
            }
        if (!removed) out += line + "\n";
    }
    return out;
}

std::string first_lines(const std::string& text, int n) {
    std::istringstream in(text);
    std::string line, out;
    for (int k = 0; k < n && std::getline(in, line); ++k) out += line + "\n";
    return out;
}

// A small valid 2.2 tetrahedron with a boundary triangle (line numbers in comments).
const std::string tet_22 =
    "$MeshFormat\n"     // 1
    "2.2 0 8\n"         // 2
    "$EndMeshFormat\n"  // 3
    "$Nodes\n"          // 4
    "4\n"               // 5
    "1 0 0 0\n"         // 6
    "2 1 0 0\n"         // 7
    "3 0 1 0\n"         // 8
    "4 0 0 1\n"         // 9
    "$EndNodes\n"       // 10
    "$Elements\n"       // 11
    "2\n"               // 12
    "1 4 2 1 1 1 2 3 4\n"  // 13
    "2 2 2 5 2 1 3 2\n"    // 14
    "$EndElements\n";      // 15

// The same in 4.1.
const std::string tet_41 =
    "$MeshFormat\n"            // 1
    "4.1 0 8\n"                // 2
    "$EndMeshFormat\n"         // 3
    "$Entities\n"              // 4
    "0 0 1 1\n"                // 5
    "1 0 0 0 1 1 0 1 5 0\n"    // 6
    "1 0 0 0 1 1 1 1 1 0\n"    // 7
    "$EndEntities\n"           // 8
    "$Nodes\n"                 // 9
    "1 4 1 4\n"                // 10
    "3 1 0 4\n"                // 11
    "1\n2\n3\n4\n"             // 12-15
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"  // 16-19
    "$EndNodes\n"              // 20
    "$Elements\n"              // 21
    "2 2 1 2\n"                // 22
    "2 1 2 1\n"                // 23
    "1 1 3 2\n"                // 24
    "3 1 4 1\n"                // 25
    "2 1 2 3 4\n"              // 26
    "$EndElements\n";          // 27

// The ParseError reading `text` throws; fails the test when it throws nothing or another type.
std::optional<ParseError> parse_error(const std::string& text) {
    try {
        read_gmsh_text("damaged.msh", text);
        ADD_FAILURE() << "no error for:\n" << text;
    } catch (const ParseError& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected a ParseError, got: " << e.what();
    }
    return std::nullopt;
}

// Checks a ParseError's file, line, expected text (substring) and found text (exact).
void expect_parse_error(const std::string& text, std::size_t line, const std::string& expected,
                        const std::string& found) {
    const auto e = parse_error(text);
    if (!e) return;
    EXPECT_EQ(e->file(), "damaged.msh");
    EXPECT_EQ(e->line(), line) << e->what();
    EXPECT_NE(e->expected().find(expected), std::string::npos) << e->what();
    EXPECT_EQ(e->found(), found) << e->what();
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
    for (char c : tet_22) {
        if (c == '\n') text += "\r\n";
        else text += c;
    }
    text = "\r\n" + text + "\r\n\r\n";
    EXPECT_EQ(read_gmsh_text("crlf.msh", text), read_gmsh_text("lf.msh", tet_22));
}

TEST(GmshRead, SmallVersion22And41FilesAgree) {
    const Mesh a = read_gmsh_text("a.msh", tet_22), b = read_gmsh_text("b.msh", tet_41);
    EXPECT_EQ(a, b);
    ASSERT_EQ(a.markers.size(), 1u);
    EXPECT_EQ(a.markers[0].name, "physical_5");
    EXPECT_EQ(a.markers[0].elements.nodes, (std::vector<NodeId>{0, 2, 1}));
}

TEST(GmshRead, ReadsFromAFileAndReportsAMissingOne) {
    const auto dir = test::scratch_dir();
    {
        std::ofstream(dir / "tet.msh") << tet_41;
    }
    EXPECT_EQ(read_gmsh(dir / "tet.msh"), read_gmsh_text("x", tet_41));
    EXPECT_THROW(read_gmsh(dir / "missing.msh"), IoError);
}

// ---- Damage: one test per kind, checking type, file, line and message. ----

TEST(GmshReadErrors, BinaryFileIsAFormatError) {
    try {
        read_gmsh_text("bin.msh", edit_lines(tet_41, {{2, "4.1 1 8"}}));
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("bin.msh"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos);
    }
}

TEST(GmshReadErrors, OtherVersionIsAFormatErrorNamingIt) {
    for (const char* version : {"4.0", "2.1", "3"}) {
        try {
            read_gmsh_text("old.msh", edit_lines(tet_22, {{2, std::string(version) + " 0 8"}}));
            FAIL() << version;
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("version ") + version), std::string::npos) << e.what();
        }
    }
}

TEST(GmshReadErrors, NotAGmshFile) {
    expect_parse_error(edit_lines(tet_22, {{1, std::nullopt}, {2, std::nullopt}, {3, std::nullopt}}), 1,
                       "$MeshFormat", "$Nodes");
    expect_parse_error("", 0, "$MeshFormat", "end of file");
    expect_parse_error(edit_lines(tet_22, {{2, "two 0 8"}}), 2, "MSH version", "two");
}

TEST(GmshReadErrors, TruncatedSection) {
    expect_parse_error(first_lines(tet_22, 8), 8, "node", "end of file");
    expect_parse_error(first_lines(tet_41, 24), 24, "element", "end of file");
}

TEST(GmshReadErrors, MissingEndMarker) {
    expect_parse_error(first_lines(tet_22, 14), 14, "$EndElements", "end of file");
    expect_parse_error(edit_lines(tet_22, {{10, std::nullopt}}), 10, "$EndNodes", "$Elements");
    expect_parse_error(tet_22 + "$Periodic\n0\n", 17, "$EndPeriodic", "end of file");
}

TEST(GmshReadErrors, CountLargerThanTheRecords) {
    expect_parse_error(edit_lines(tet_22, {{5, "5"}}), 10, "node", "$EndNodes");
    expect_parse_error(edit_lines(tet_41, {{22, "3 2 1 2"}}), 27, "element block header", "$EndElements");
}

TEST(GmshReadErrors, CountSmallerThanTheRecords) {
    expect_parse_error(edit_lines(tet_22, {{5, "3"}}), 9, "$EndNodes", "4 0 0 1");
}

TEST(GmshReadErrors, BlockSizesDisagreeWithTheSectionHeader) {
    expect_parse_error(edit_lines(tet_41, {{10, "1 5 1 4"}}), 10, "sum over the node blocks (4)", "5");
    expect_parse_error(edit_lines(tet_41, {{11, "3 1 0 5"}}), 11, "at most 4 nodes in this block", "5");
    expect_parse_error(edit_lines(tet_41, {{22, "2 3 1 2"}}), 22, "sum over the element blocks (2)", "3");
}

TEST(GmshReadErrors, BadNumber) {
    expect_parse_error(edit_lines(tet_22, {{7, "2 1,5 0 0"}}), 7, "x coordinate", "1,5");
    expect_parse_error(edit_lines(tet_41, {{17, "1 nan 0"}}), 17, "y coordinate", "nan");
    expect_parse_error(edit_lines(tet_22, {{13, "1 4 2 1 1 1 2 3 4.0"}}), 13, "node tags of a tetrahedron", "4.0");
    expect_parse_error(edit_lines(tet_22, {{5, "-4"}}), 5, "count", "-4");
}

TEST(GmshReadErrors, RecordWithExtraTokens) {
    expect_parse_error(edit_lines(tet_22, {{14, "2 2 2 5 2 1 3 2 4"}}), 14, "end of the line", "4");
    expect_parse_error(edit_lines(tet_22, {{13, "1 4 2 1 1 1 2 3"}}), 13, "node tags of a tetrahedron",
                       "end of line");
}

TEST(GmshReadErrors, UnsupportedElementType) {
    expect_parse_error(edit_lines(tet_22, {{13, "1 11 2 1 1 1 2 3 4 1 2 3 4 1 2"}}), 13,
                       "supported Gmsh element type", "11");
    expect_parse_error(edit_lines(tet_41, {{25, "3 1 29 1"}}), 25, "supported Gmsh element type", "29");
}

TEST(GmshReadErrors, ElementTypeOfAnotherDimensionThanItsEntity) {
    expect_parse_error(edit_lines(tet_41, {{23, "3 1 2 1"}}), 23, "dimension 3", "triangle");
}

TEST(GmshReadErrors, UndefinedNodeTag) {
    expect_parse_error(edit_lines(tet_22, {{14, "2 2 2 5 2 1 3 9"}}), 14, "node tag defined in $Nodes", "9");
    expect_parse_error(edit_lines(tet_41, {{24, "1 1 3 7"}}), 24, "node tag defined in $Nodes", "7");
}

TEST(GmshReadErrors, DuplicateOrNonPositiveNodeTag) {
    expect_parse_error(edit_lines(tet_22, {{7, "1 1 0 0"}}), 7, "node tag not used before", "1");
    expect_parse_error(edit_lines(tet_41, {{13, "0"}}), 13, "positive node tag", "0");
}

TEST(GmshReadErrors, SectionsOutOfOrderOrRepeated) {
    // $Elements before $Nodes.
    const std::string swapped = first_lines(tet_22, 3) + "$Elements\n0\n$EndElements\n$Nodes\n0\n$EndNodes\n";
    expect_parse_error(swapped, 4, "$Nodes before $Elements", "$Elements");
    expect_parse_error(tet_22 + "$Nodes\n0\n$EndNodes\n", 16, "a single $Nodes section", "$Nodes");
    expect_parse_error(first_lines(tet_22, 10), 10, "an $Elements section", "end of file");
    expect_parse_error(edit_lines(tet_22, {{11, "$EndElements"}}), 11, "section header", "$EndElements");
    expect_parse_error(edit_lines(tet_22, {{11, "Elements"}}), 11, "section header", "Elements");
}

TEST(GmshReadErrors, BadPhysicalName) {
    const std::string names = "$PhysicalNames\n1\n2 5 wall\n$EndPhysicalNames\n";
    expect_parse_error(first_lines(tet_22, 3) + names, 6, "double quotes", "wall");
    const std::string dims = "$PhysicalNames\n1\n4 5 \"wall\"\n$EndPhysicalNames\n";
    expect_parse_error(first_lines(tet_22, 3) + dims, 6, "0, 1, 2 or 3", "4");
}

TEST(GmshReadErrors, PartitionedMeshIsAFormatError) {
    EXPECT_THROW(read_gmsh_text("part.msh", edit_lines(tet_41, {{4, "$PartitionedEntities"}, {8, "$EndPartitionedEntities"}})),
                 FormatError);
}

TEST(GmshReadErrors, TwoDimensionalMeshOffTheZeroPlaneIsAMeshError) {
    const std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0.5\n"
                             "$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n";
    try {
        read_gmsh_text("tilted.msh", text);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_EQ(e.index(), 2);
        EXPECT_NE(std::string(e.what()).find("tilted.msh"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("z = 0"), std::string::npos);
    }
}

TEST(GmshReadErrors, MeshWithoutSurfaceOrVolumeElementsIsAMeshError) {
    const std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n"
                             "$EndNodes\n$Elements\n1\n1 1 2 0 1 1 2\n$EndElements\n";
    EXPECT_THROW(read_gmsh_text("lines.msh", text), MeshError);
}

TEST(GmshReadErrors, HugeCountsFailFastWithoutAllocating) {
    // Each claims 10^12 records (or 2·10^9 nodes, just under the NodeId limit)
    // and holds one or two: the reader must report the short section, not
    // try to reserve memory for the count.
    const std::string huge = "1000000000000";
    const std::vector<std::string> texts = {
        edit_lines(tet_22, {{5, huge}}),
        edit_lines(tet_22, {{5, "2000000000"}}),
        edit_lines(tet_22, {{12, huge}}),
        edit_lines(tet_41, {{5, "0 0 " + huge + " 1"}}),
        edit_lines(tet_41, {{10, "1 2000000000 1 4"}, {11, "3 1 0 2000000000"}}),
        edit_lines(tet_41, {{10, huge + " 4 1 4"}}),
        edit_lines(tet_41, {{22, "2 " + huge + " 1 2"}, {25, "3 1 4 " + huge}}),
        edit_lines(tet_41, {{6, "1 0 0 0 1 1 0 " + huge + " 5 0"}}),
        first_lines(tet_22, 3) + "$PhysicalNames\n" + huge + "\n1 1 \"a\"\n$EndPhysicalNames\n",
    };
    for (const std::string& text : texts) {
        const auto e = parse_error(text);
        ASSERT_TRUE(e.has_value()) << text;
        EXPECT_GT(e->line(), 0u);
    }
    // Over the NodeId range: refused from the count itself.
    expect_parse_error(edit_lines(tet_22, {{5, huge}}), 5, "at most 2147483647 nodes", huge);
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
        const auto counts = test::count_by_type(m.cells);
        EXPECT_EQ(counts.at(CellType::prism), prisms);
        EXPECT_EQ(counts.at(CellType::hexahedron), hexes);
        ASSERT_EQ(m.markers.size(), 1u);
        EXPECT_EQ(m.markers[0].elements.size(), test::gmsh_group_size(2, 1));
        for (std::size_t i = 0; i < m.cells.size(); ++i)
            EXPECT_GT(vtk_corner_orientation(m, i), 0)
                << cell_type_name(m.cells.types[i]) << " " << i << " is inverted in VTK order";
    }
}
