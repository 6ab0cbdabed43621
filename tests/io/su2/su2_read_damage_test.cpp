// Damaged SU2 input: every kind of damage must give a ParseError naming the
// file, the line and what was expected (never a crash, a hang or garbage).
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/su2/su2.hpp"

using namespace dgwarp;

namespace {

// A valid 2D mesh; the comments give the line numbers the tests refer to.
const std::vector<std::string> base_lines = {
    "NDIME= 2",             // 1
    "NELEM= 2",             // 2
    "5 0 1 2 0",            // 3
    "5 0 2 3 1",            // 4
    "NPOIN= 4",             // 5
    "0 0 0",                // 6
    "1 0 1",                // 7
    "1 1 2",                // 8
    "0 1 3",                // 9
    "NMARK= 2",             // 10
    "MARKER_TAG= lower",    // 11
    "MARKER_ELEMS= 1",      // 12
    "3 0 1",                // 13
    "MARKER_TAG= upper",    // 14
    "MARKER_ELEMS= 2",      // 15
    "3 1 2",                // 16
    "3 2 3",                // 17
};

std::string join(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

/// The base text with line `line` (1-based) replaced.
std::string with_line(std::size_t line, const std::string& text) {
    auto lines = base_lines;
    lines.at(line - 1) = text;
    return join(lines);
}

/// The base text without lines first..last (1-based, inclusive).
std::string without_lines(std::size_t first, std::size_t last) {
    auto lines = base_lines;
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(first - 1), lines.begin() + static_cast<std::ptrdiff_t>(last));
    return join(lines);
}

/// The first `n` lines of the base text.
std::string first_lines(std::size_t n) {
    return join(std::vector<std::string>(base_lines.begin(), base_lines.begin() + static_cast<std::ptrdiff_t>(n)));
}

/// Reading `text` throws a ParseError at `line` whose expected-text contains
/// `expected` and whose found-text is `found` (when given).
void expect_parse_error(const std::string& text, std::size_t line, const std::string& expected,
                        const char* found = nullptr) {
    try {
        read_su2_text("damaged.su2", text);
        ADD_FAILURE() << "no error for:\n" << text;
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "damaged.su2");
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.expected().find(expected), std::string::npos) << e.what();
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("damaged.su2", 0), 0u) << what;
        EXPECT_NE(what.find(expected), std::string::npos) << what;
        if (found) {
            EXPECT_EQ(e.found(), found) << what;
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type: " << e.what();
    }
}

}  // namespace

TEST(Su2ReadDamage, TheBaseTextIsValid) {
    const Mesh m = read_su2_text("base.su2", join(base_lines));
    EXPECT_EQ(m.num_points(), 4u);
    EXPECT_EQ(m.cells.size(), 2u);
    EXPECT_EQ(m.markers.size(), 2u);
}

TEST(Su2ReadDamage, TruncatedFile) {
    expect_parse_error(first_lines(3), 3, "element 2 of the 2 announced by NELEM= on line 2", "end of file");
    expect_parse_error(first_lines(7), 7, "point 3 of the 4 announced by NPOIN= on line 5", "end of file");
    expect_parse_error(first_lines(16), 16, "boundary element 2 of the 2 announced by MARKER_ELEMS= on line 15",
                       "end of file");
    expect_parse_error(first_lines(11), 11, "MARKER_ELEMS= after MARKER_TAG= lower", "end of file");
    expect_parse_error(first_lines(13), 13, "MARKER_TAG= of marker 2 of the 2 announced by NMARK= on line 10",
                       "end of file");
    // Cut in the middle of a line.
    expect_parse_error(join(base_lines).substr(0, join(base_lines).find("0 2 3 1") + 3), 4, "node 3 of the triangle",
                       "end of line");
}

TEST(Su2ReadDamage, CountLargerThanTheRecords) {
    expect_parse_error(with_line(2, "NELEM= 3"), 5, "element 3 of the 3 announced by NELEM= on line 2", "NPOIN= 4");
    expect_parse_error(with_line(5, "NPOIN= 5"), 10, "point 5 of the 5 announced by NPOIN= on line 5", "NMARK= 2");
    expect_parse_error(with_line(12, "MARKER_ELEMS= 2"), 14, "boundary element 2 of the 2", "MARKER_TAG= upper");
    expect_parse_error(with_line(10, "NMARK= 3"), 17, "MARKER_TAG= of marker 3 of the 3", "end of file");
}

TEST(Su2ReadDamage, CountSmallerThanTheRecords) {
    expect_parse_error(with_line(2, "NELEM= 1"), 4, "a keyword line after the 1 elements announced by NELEM= on line 2",
                       "5 0 2 3 1");
    expect_parse_error(with_line(5, "NPOIN= 3"), 9, "a keyword line after the 3 points announced by NPOIN= on line 5",
                       "0 1 3");
    expect_parse_error(with_line(15, "MARKER_ELEMS= 1"), 17,
                       "a keyword line after the 1 boundary elements announced by MARKER_ELEMS= on line 15", "3 2 3");
    expect_parse_error(with_line(10, "NMARK= 1"), 14, "the last of the 1 markers announced by NMARK= on line 10",
                       "MARKER_TAG= upper");
}

TEST(Su2ReadDamage, BadNumbers) {
    for (const char* bad : {"abc", "nan", "NaN", "inf", "-inf", "1e999", "1.0.0", "0x10", "1,5"})
        expect_parse_error(with_line(7, std::string(bad) + " 0 1"), 7,
                           "coordinate 1 of 2 (a finite number) in point 2 of the 4 announced by NPOIN= on line 5",
                           bad);
    expect_parse_error(with_line(8, "1 nan 2"), 8, "coordinate 2 of 2 (a finite number) in point 3", "nan");
    expect_parse_error(with_line(8, "1"), 8, "coordinate 2 of 2", "end of line");
    expect_parse_error(with_line(3, "5 0 x1 2 0"), 3,
                       "node 2 of the triangle (an integer node id) in element 1 of the 2 announced by NELEM= on line 2",
                       "x1");
    expect_parse_error(with_line(3, "5 0 1.5 2 0"), 3, "node 2 of the triangle (an integer node id)", "1.5");
    expect_parse_error(with_line(3, "five 0 1 2 0"), 3, "an integer element type id in element 1", "five");
    expect_parse_error(with_line(16, "3 1"), 16, "node 2 of the line (an integer node id) in boundary element 1",
                       "end of line");
    expect_parse_error(with_line(2, "NELEM= many"), 2, "a positive element count after NELEM=", "many");
    expect_parse_error(with_line(2, "NELEM="), 2, "a positive element count after NELEM=", "nothing");
    expect_parse_error(with_line(1, "NDIME= two"), 1, "dimension 2 or 3 after NDIME=", "two");
}

TEST(Su2ReadDamage, UnknownElementType) {
    expect_parse_error(with_line(3, "7 0 1 2 0"), 3, "a known element type id (1 vertex, 3 line, 5 triangle", "7");
    expect_parse_error(with_line(3, "-5 0 1 2 0"), 3, "a known element type id", "-5");
    expect_parse_error(with_line(13, "99999999999 0 1"), 13, "a known element type id", "99999999999");
}

TEST(Su2ReadDamage, ElementOfTheWrongDimension) {
    expect_parse_error(with_line(3, "10 0 1 2 3 0"), 3, "a cell of a 2D mesh (5 triangle, 9 quadrilateral)",
                       "10 (tetrahedron)");
    expect_parse_error(with_line(3, "3 0 1 0"), 3, "a cell of a 2D mesh", "3 (line)");
    expect_parse_error(with_line(13, "5 0 1 2"), 13, "a boundary element of a 2D mesh (1 vertex, 3 line)",
                       "5 (triangle)");
    expect_parse_error("NDIME= 3\nNELEM= 1\n5 0 1 2 0\nNPOIN= 3\n0 0 0\n1 0 0\n0 1 0\nNMARK= 0\n", 3,
                       "a cell of a 3D mesh (10 tetrahedron, 12 hexahedron, 13 prism, 14 pyramid)", "5 (triangle)");
    expect_parse_error(
        "NDIME= 3\nNELEM= 1\n10 0 1 2 3 0\nNPOIN= 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nNMARK= 1\nMARKER_TAG= a\n"
        "MARKER_ELEMS= 1\n3 0 1\n",
        12, "a boundary element of a 3D mesh (5 triangle, 9 quadrilateral)", "3 (line)");
    expect_parse_error(with_line(1, "NDIME= 4"), 1, "dimension 2 or 3 after NDIME=", "4");
}

TEST(Su2ReadDamage, NodeIdOutOfRangeOrNegative) {
    expect_parse_error(with_line(3, "5 0 1000000000 2 0"), 3,
                       "node ids below 4, the number of points (NPOIN= on line 5)", "1000000000");
    expect_parse_error(with_line(4, "5 0 2 4 1"), 4, "node ids below 4", "4");
    expect_parse_error(with_line(17, "3 2 4"), 17, "node ids below 4", "4");
    expect_parse_error(with_line(3, "5 0 -1 2 0"), 3, "a node id >= 0 in element 1", "-1");
    expect_parse_error(with_line(13, "3 -7 1"), 13, "a node id >= 0 in boundary element 1", "-7");
    expect_parse_error(with_line(3, "5 0 1000000000000 2 0"), 3, "a node id below 2147483647", "1000000000000");
    expect_parse_error(with_line(3, "5 0 2147483647 2 0"), 3, "a node id below 2147483647", "2147483647");
    expect_parse_error(with_line(3, "5 0 99999999999999999999 2 0"), 3, "an integer node id",
                       "99999999999999999999");
}

TEST(Su2ReadDamage, MissingSection) {
    expect_parse_error(without_lines(1, 1), 1, "NDIME= before NELEM=", "NELEM= 2");
    expect_parse_error(without_lines(2, 4), 14, "the NELEM= section", "end of file");
    expect_parse_error(without_lines(5, 9), 12, "the NPOIN= section", "end of file");
    expect_parse_error(first_lines(9), 9, "the NMARK= section", "end of file");
    expect_parse_error("", 0, "the NDIME=, NELEM=, NPOIN= and NMARK= sections", "end of file");
    expect_parse_error("% only a comment\n\n", 2, "the NDIME=, NELEM=, NPOIN= and NMARK= sections", "end of file");
    expect_parse_error("NDIME= 2\n", 1, "the NELEM=, NPOIN= and NMARK= sections", "end of file");
    expect_parse_error("0 0 0\n", 1, "a keyword line such as NDIME=", "0 0 0");
}

TEST(Su2ReadDamage, MissingMarkerElems) {
    expect_parse_error(without_lines(12, 12), 12, "MARKER_ELEMS= after MARKER_TAG= lower", "3 0 1");
    expect_parse_error(without_lines(14, 14), 14, "MARKER_TAG= of marker 2 of the 2", "MARKER_ELEMS= 2");
    expect_parse_error(without_lines(11, 11), 11, "MARKER_TAG= of marker 1 of the 2", "MARKER_ELEMS= 1");
    expect_parse_error(with_line(11, "MARKER_TAG="), 11, "a marker name after MARKER_TAG=");
    expect_parse_error(with_line(14, "MARKER_TAG= lower"), 14, "a marker name not used before", "lower");
}

TEST(Su2ReadDamage, NegativeCounts) {
    expect_parse_error(with_line(2, "NELEM= -1"), 2, "a positive element count after NELEM=", "-1");
    expect_parse_error(with_line(5, "NPOIN= -4"), 5, "a non-negative point count after NPOIN=", "-4");
    expect_parse_error(with_line(10, "NMARK= -2"), 10, "a non-negative marker count after NMARK=", "-2");
    expect_parse_error(with_line(12, "MARKER_ELEMS= -1"), 12, "a non-negative boundary element count", "-1");
    expect_parse_error("NZONE= 0\n", 1, "a positive zone count after NZONE=", "0");
}

TEST(Su2ReadDamage, AbsurdCountsFailAtTheHeaderBeforeAnyAllocation) {
    // 10^12 records cannot fit in the rest of a 100-byte text: the error is on
    // the header line itself, before any record is read or memory reserved.
    const std::string huge = "1000000000000";
    expect_parse_error(with_line(2, "NELEM= " + huge), 2, "element count that the rest of the file can hold", huge.c_str());
    expect_parse_error(with_line(5, "NPOIN= " + huge), 5, "point count that the rest of the file can hold", huge.c_str());
    expect_parse_error(with_line(10, "NMARK= " + huge), 10, "marker count that the rest of the file can hold",
                       huge.c_str());
    expect_parse_error(with_line(12, "MARKER_ELEMS= " + huge), 12, "boundary element count that the rest of the file",
                       huge.c_str());
    expect_parse_error("NDIME= 3\nNZONE= " + huge + "\n", 2, "zone count that the rest of the file can hold",
                       huge.c_str());
    expect_parse_error(with_line(2, "NELEM= 9223372036854775807"), 2, "element count that the rest of the file");
    expect_parse_error(with_line(2, "NELEM= 99999999999999999999"), 2, "a positive element count");
    // Just above the bound: 3 triangle lines need at least 3 × 8 - 1 bytes, not 8.
    expect_parse_error("NDIME= 2\nNELEM= 3\n5 0 1 2\n", 2, "element count that the rest of the file can hold", "3");
}

TEST(Su2ReadDamage, DuplicateSections) {
    std::vector<std::string> lines = base_lines;
    lines.insert(lines.begin() + 4, {"NELEM= 1", "5 0 1 2"});
    expect_parse_error(join(lines), 5, "NELEM= already appeared on line 2", "NELEM= 1");
}

TEST(Su2ReadDamage, ZoneKeywordsInTheWrongPlace) {
    expect_parse_error("IZONE= 1\n", 1, "NZONE= before IZONE=", "IZONE= 1");
    expect_parse_error("NZONE= 2\nIZONE= 1\nNDIME= 2\nNELEM= 1\n5 0 1 2\nIZONE= 2\n", 6,
                       "the NPOIN=, NMARK= sections of zone 1",
                       "IZONE= 2");
    expect_parse_error("NZONE= 2\nIZONE= one\n", 2, "a zone number after IZONE=", "one");
}

TEST(Su2ReadDamage, EveryPrefixOfAValidFileFailsCleanly) {
    // Cutting the file anywhere must give a ParseError, never a crash or a
    // mesh (except at the very end, where only the final newline is missing).
    const std::string text = join(base_lines);
    for (std::size_t n = 0; n + 1 < text.size(); ++n) {
        const std::string prefix = text.substr(0, n);
        if (prefix == text.substr(0, text.size() - 1)) continue;
        EXPECT_THROW(read_su2_text("prefix.su2", prefix), ParseError) << "prefix of " << n << " bytes";
    }
}

TEST(Su2ReadDamage, RandomByteDamageGivesAParseErrorOrAValidMesh) {
    // Seeded random edits of the base text (bytes replaced, deleted or
    // inserted, lines duplicated): the reader either returns a mesh that
    // passes validate() or throws ParseError; never anything else.
    const std::string base = join(base_lines);
    const std::string alphabet = "0123456789-+.eE =\t\r\n%xNMAK_";
    std::mt19937 rng(20240611);
    int parse_errors = 0, meshes = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::string text = base;
        const int edits = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < edits && !text.empty(); ++k) {
            const std::size_t at = rng() % text.size();
            const char c = alphabet[rng() % alphabet.size()];
            switch (rng() % 4) {
                case 0: text[at] = c; break;
                case 1: text.erase(at, 1); break;
                case 2: text.insert(at, 1, c); break;
                default: {
                    const std::size_t start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
                    const std::size_t end = text.find('\n', at);
                    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
                    text.insert(start, line);
                }
            }
        }
        try {
            const Mesh m = read_su2_text("fuzz.su2", text);
            EXPECT_NO_THROW(validate(m));
            ++meshes;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.file(), "fuzz.su2");
            ++parse_errors;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "unexpected " << e.what() << " for:\n" << text;
        }
    }
    EXPECT_GT(parse_errors, 10000);  // most edits break the file...
    EXPECT_GT(meshes, 100);          // ...but some (a blank, a comment) do not
}
