// TextReader: what every text mesh reader (SU2, Gmsh) reads its lines through.
#include "dgwarp/io/text_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/su2/su2.hpp"

using namespace dgwarp;

namespace {

const std::string utf8_bom = "\xEF\xBB\xBF";

const char* const bom_test_su2 =
    "NDIME= 2\n"
    "NELEM= 2\n"
    "5 0 1 2 0\n"
    "5 0 2 3 1\n"
    "NPOIN= 4\n"
    "0 0 0\n"
    "1 0 1\n"
    "1 1 2\n"
    "0 1 3\n"
    "NMARK= 1\n"
    "MARKER_TAG= wall\n"
    "MARKER_ELEMS= 4\n"
    "3 0 1\n"
    "3 1 2\n"
    "3 2 3\n"
    "3 3 0\n";

void expect_same_mesh(const Mesh& a, const Mesh& b) {
    EXPECT_EQ(a.dim, b.dim);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.cells, b.cells);
    ASSERT_EQ(a.markers.size(), b.markers.size());
    for (std::size_t m = 0; m < a.markers.size(); ++m) EXPECT_EQ(a.markers[m].name, b.markers[m].name);
}

}  // namespace

TEST(TextReader, AUtf8ByteOrderMarkIsSkipped) {
    // Issue #27, item 15: editors on Windows start UTF-8 files with one; it made the first line
    // "NDIME= 2" look like something else ("expected a keyword line such as NDIME=, found 'NDIME= 2'").
    TextReader r("x.su2", utf8_bom + "NDIME= 2\nNPOIN= 0\n");
    ASSERT_TRUE(r.next_line());
    EXPECT_EQ(r.line(), "NDIME= 2");
    EXPECT_EQ(r.line_number(), 1u);
    TextReader only("x.su2", utf8_bom);
    EXPECT_FALSE(only.next_nonblank_line());
}

TEST(TextReader, Su2AndGmshFilesWithAByteOrderMarkReadAsWithout) {
    const Mesh plain = read_su2_text("plain.su2", bom_test_su2);
    expect_same_mesh(read_su2_text("bom.su2", utf8_bom + bom_test_su2), plain);
    for (int version : {41, 22}) {
        std::ostringstream msh;
        write_gmsh(msh, plain, version);
        expect_same_mesh(read_gmsh_text("bom.msh", utf8_bom + msh.str()), read_gmsh_text("plain.msh", msh.str()));
    }
}
