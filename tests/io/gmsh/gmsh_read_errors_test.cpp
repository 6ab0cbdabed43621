// Damaged Gmsh files: one test per kind of damage, each checking the error
// type, file, line and what was expected.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "io/gmsh/gmsh_test_support.hpp"

using namespace dgwarp;

namespace {

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

TEST(GmshReadErrors, BinaryFileIsAFormatError) {
    try {
        read_gmsh_text("bin.msh", edit_lines(test::tet_41, {{2, "4.1 1 8"}}));
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("bin.msh"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("binary"), std::string::npos);
    }
}

TEST(GmshReadErrors, OtherVersionIsAFormatErrorNamingIt) {
    for (const char* version : {"4.0", "2.1", "3"}) {
        try {
            read_gmsh_text("old.msh", edit_lines(test::tet_22, {{2, std::string(version) + " 0 8"}}));
            FAIL() << version;
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("version ") + version), std::string::npos) << e.what();
        }
    }
}

TEST(GmshReadErrors, NotAGmshFile) {
    expect_parse_error(edit_lines(test::tet_22, {{1, std::nullopt}, {2, std::nullopt}, {3, std::nullopt}}), 1,
                       "$MeshFormat", "$Nodes");
    expect_parse_error("", 0, "$MeshFormat", "end of file");
    expect_parse_error(edit_lines(test::tet_22, {{2, "two 0 8"}}), 2, "MSH version", "two");
}

TEST(GmshReadErrors, TruncatedSection) {
    expect_parse_error(first_lines(test::tet_22, 8), 8, "node", "end of file");
    expect_parse_error(first_lines(test::tet_41, 24), 24, "element", "end of file");
}

TEST(GmshReadErrors, MissingEndMarker) {
    expect_parse_error(first_lines(test::tet_22, 14), 14, "$EndElements", "end of file");
    expect_parse_error(edit_lines(test::tet_22, {{10, std::nullopt}}), 10, "$EndNodes", "$Elements");
    expect_parse_error(test::tet_22 + "$Periodic\n0\n", 17, "$EndPeriodic", "end of file");
}

TEST(GmshReadErrors, CountLargerThanTheRecords) {
    expect_parse_error(edit_lines(test::tet_22, {{5, "5"}}), 10, "node", "$EndNodes");
    expect_parse_error(edit_lines(test::tet_41, {{22, "3 2 1 2"}}), 27, "element block header", "$EndElements");
}

TEST(GmshReadErrors, CountSmallerThanTheRecords) {
    expect_parse_error(edit_lines(test::tet_22, {{5, "3"}}), 9, "$EndNodes", "4 0 0 1");
}

TEST(GmshReadErrors, BlockSizesDisagreeWithTheSectionHeader) {
    expect_parse_error(edit_lines(test::tet_41, {{10, "1 5 1 4"}}), 10, "sum over the node blocks (4)", "5");
    expect_parse_error(edit_lines(test::tet_41, {{11, "3 1 0 5"}}), 11, "at most 4 nodes in this block", "5");
    expect_parse_error(edit_lines(test::tet_41, {{22, "2 3 1 2"}}), 22, "sum over the element blocks (2)", "3");
}

TEST(GmshReadErrors, BadNumber) {
    expect_parse_error(edit_lines(test::tet_22, {{7, "2 1,5 0 0"}}), 7, "x coordinate", "1,5");
    expect_parse_error(edit_lines(test::tet_41, {{17, "1 nan 0"}}), 17, "y coordinate", "nan");
    expect_parse_error(edit_lines(test::tet_22, {{13, "1 4 2 1 1 1 2 3 4.0"}}), 13, "node tags of a tetrahedron", "4.0");
    expect_parse_error(edit_lines(test::tet_22, {{5, "-4"}}), 5, "count", "-4");
}

TEST(GmshReadErrors, RecordWithExtraTokens) {
    expect_parse_error(edit_lines(test::tet_22, {{14, "2 2 2 5 2 1 3 2 4"}}), 14, "end of the line", "4");
    expect_parse_error(edit_lines(test::tet_22, {{13, "1 4 2 1 1 1 2 3"}}), 13, "node tags of a tetrahedron",
                       "end of line");
}

TEST(GmshReadErrors, UnsupportedElementType) {
    expect_parse_error(edit_lines(test::tet_22, {{13, "1 11 2 1 1 1 2 3 4 1 2 3 4 1 2"}}), 13,
                       "supported Gmsh element type", "11");
    expect_parse_error(edit_lines(test::tet_41, {{25, "3 1 29 1"}}), 25, "supported Gmsh element type", "29");
}

TEST(GmshReadErrors, ElementTypeOfAnotherDimensionThanItsEntity) {
    expect_parse_error(edit_lines(test::tet_41, {{23, "3 1 2 1"}}), 23, "dimension 3", "triangle");
}

TEST(GmshReadErrors, UndefinedNodeTag) {
    expect_parse_error(edit_lines(test::tet_22, {{14, "2 2 2 5 2 1 3 9"}}), 14, "node tag defined in $Nodes", "9");
    expect_parse_error(edit_lines(test::tet_41, {{24, "1 1 3 7"}}), 24, "node tag defined in $Nodes", "7");
}

TEST(GmshReadErrors, DuplicateOrNonPositiveNodeTag) {
    expect_parse_error(edit_lines(test::tet_22, {{7, "1 1 0 0"}}), 7, "node tag not used before", "1");
    expect_parse_error(edit_lines(test::tet_41, {{13, "0"}}), 13, "positive node tag", "0");
}

TEST(GmshReadErrors, SectionsOutOfOrderOrRepeated) {
    // $Elements before $Nodes.
    const std::string swapped = first_lines(test::tet_22, 3) + "$Elements\n0\n$EndElements\n$Nodes\n0\n$EndNodes\n";
    expect_parse_error(swapped, 4, "$Nodes before $Elements", "$Elements");
    expect_parse_error(test::tet_22 + "$Nodes\n0\n$EndNodes\n", 16, "a single $Nodes section", "$Nodes");
    expect_parse_error(first_lines(test::tet_22, 10), 10, "an $Elements section", "end of file");
    expect_parse_error(edit_lines(test::tet_22, {{11, "$EndElements"}}), 11, "section header", "$EndElements");
    expect_parse_error(edit_lines(test::tet_22, {{11, "Elements"}}), 11, "section header", "Elements");
}

TEST(GmshReadErrors, BadPhysicalName) {
    const std::string names = "$PhysicalNames\n1\n2 5 wall\n$EndPhysicalNames\n";
    expect_parse_error(first_lines(test::tet_22, 3) + names, 6, "double quotes", "wall");
    const std::string dims = "$PhysicalNames\n1\n4 5 \"wall\"\n$EndPhysicalNames\n";
    expect_parse_error(first_lines(test::tet_22, 3) + dims, 6, "0, 1, 2 or 3", "4");
}

TEST(GmshReadErrors, TwoPhysicalGroupsOfOneNameAreAMeshErrorNamingBoth) {
    // Issue #27: "farfield" renamed "airfoil" made one marker of both, and a
    // motion of "airfoil" moved the far field too. The SU2 reader refuses it.
    const std::string text = first_lines(test::tet_22, 3) +
                             "$PhysicalNames\n2\n2 5 \"wall\"\n2 6 \"wall\"\n$EndPhysicalNames\n" +
                             edit_lines(test::tet_22, {{1, std::nullopt}, {2, std::nullopt}, {3, std::nullopt},
                                                       {12, "3"}, {15, "3 2 2 6 3 1 2 4\n$EndElements"}});
    try {
        read_gmsh_text("twice.msh", text);
        FAIL() << "accepted:\n" << text;
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "wall");
        const std::string what = e.what();
        EXPECT_NE(what.find("twice.msh"), std::string::npos) << what;
        EXPECT_NE(what.find("physical groups 5 and 6"), std::string::npos) << what;
    }
    // Distinct names read as two markers.
    std::string distinct = text;
    distinct.replace(distinct.find("6 \"wall\""), 8, "6 \"side\"");
    const Mesh mesh = read_gmsh_text("distinct.msh", distinct);
    ASSERT_EQ(mesh.markers.size(), 2u);
    EXPECT_EQ(mesh.markers[1].name, "side");
}

TEST(GmshReadErrors, PartitionedMeshIsAFormatError) {
    EXPECT_THROW(read_gmsh_text("part.msh", edit_lines(test::tet_41, {{4, "$PartitionedEntities"}, {8, "$EndPartitionedEntities"}})),
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
        edit_lines(test::tet_22, {{5, huge}}),
        edit_lines(test::tet_22, {{5, "2000000000"}}),
        edit_lines(test::tet_22, {{12, huge}}),
        edit_lines(test::tet_41, {{5, "0 0 " + huge + " 1"}}),
        edit_lines(test::tet_41, {{10, "1 2000000000 1 4"}, {11, "3 1 0 2000000000"}}),
        edit_lines(test::tet_41, {{10, huge + " 4 1 4"}}),
        edit_lines(test::tet_41, {{22, "2 " + huge + " 1 2"}, {25, "3 1 4 " + huge}}),
        edit_lines(test::tet_41, {{6, "1 0 0 0 1 1 0 " + huge + " 5 0"}}),
        first_lines(test::tet_22, 3) + "$PhysicalNames\n" + huge + "\n1 1 \"a\"\n$EndPhysicalNames\n",
    };
    for (const std::string& text : texts) {
        const auto e = parse_error(text);
        ASSERT_TRUE(e.has_value()) << text;
        EXPECT_GT(e->line(), 0u);
    }
    // Over the NodeId range: refused from the count itself.
    expect_parse_error(edit_lines(test::tet_22, {{5, huge}}), 5, "at most 2147483647 nodes", huge);
}
