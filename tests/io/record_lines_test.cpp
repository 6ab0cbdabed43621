// Blocks of records parsed on several threads (record_lines.hpp) and the SU2
// reader's fast path over them: the same mesh and the same errors as the
// line-by-line code, whatever the chunks and the thread count.
#include "dgwarp/io/record_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/text_reader.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

// "HEAD\n" then n records "i 2i" with a blank line after every 7th and a '%'
// comment after every 11th, CRLF endings on odd records; then "TAIL".
std::string records_text(int n) {
    std::string s = "HEAD\n";
    for (int i = 0; i < n; ++i) {
        s += std::to_string(i) + " " + std::to_string(2 * i) + (i % 2 ? "\r\n" : "\n");
        if (i % 7 == 6) s += "   \t\n";
        if (i % 11 == 10) s += "  % a comment\n";
    }
    return s + "TAIL\n";
}

}  // namespace

TEST(RecordLines, ChunksCoverTheRecordsWithTheirLineNumbers) {
    const int n = 1000;
    TextReader r("t.txt", records_text(n));
    ASSERT_TRUE(r.next_line());  // HEAD, line 1
    const auto block = split_record_lines(r, n, SkippedLines{'%'}, 64);
    ASSERT_TRUE(block);
    ASSERT_EQ(block->chunks.size(), (n + 63) / 64u);
    // Brute force: walk the lines one by one.
    TextReader walk("t.txt", records_text(n));
    walk.next_line();
    std::vector<std::size_t> line_of(n);
    for (int i = 0; i < n;) {
        ASSERT_TRUE(walk.next_line());
        if (!skipped_line(walk.line(), SkippedLines{'%'})) line_of[static_cast<std::size_t>(i++)] = walk.line_number();
    }
    std::int64_t seen = 0;
    for (const RecordChunk& c : block->chunks) {
        EXPECT_EQ(c.first, seen);
        EXPECT_TRUE(for_each_record_line(r.content(), c, SkippedLines{'%'},
                                         [&](std::string_view line, std::int64_t record, std::size_t line_number) {
                                             EXPECT_EQ(record, seen);
                                             EXPECT_EQ(line, std::to_string(record) + " " + std::to_string(2 * record));
                                             EXPECT_EQ(line_number, line_of[static_cast<std::size_t>(record)]);
                                             ++seen;
                                             return true;
                                         }));
    }
    EXPECT_EQ(seen, n);
    EXPECT_EQ(block->last_line, line_of.back());
    // The reader continues after the last record as if it had read it.
    r.seek(block->end, block->last_line);
    EXPECT_EQ(r.line(), std::to_string(n - 1) + " " + std::to_string(2 * (n - 1)));
    ASSERT_TRUE(r.next_nonblank_line());
    while (skipped_line(r.line(), SkippedLines{'%'})) ASSERT_TRUE(r.next_nonblank_line());
    EXPECT_EQ(r.line(), "TAIL");
    const std::string text = records_text(n);
    EXPECT_EQ(r.line_number(), static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')));
    // Fewer records than asked for: nullopt.
    TextReader short_reader("t.txt", records_text(10));
    short_reader.next_line();
    EXPECT_FALSE(split_record_lines(short_reader, 12, SkippedLines{'%'}, 4));
}

TEST(RecordLines, ALargeBlockSplitOnThreadsCoversItsRecordsWithTheirLineNumbers) {
    // 150,000 records (about 2 MB: split in byte ranges on the threads), then
    // TAIL; with and without a last line end, and with too few records.
    const int n = 150000;
    std::string text = records_text(n);
    std::vector<std::size_t> line_of(n);
    {
        TextReader walk("t.txt", text);
        walk.next_line();
        for (int i = 0; i < n;) {
            ASSERT_TRUE(walk.next_line());
            if (!skipped_line(walk.line(), SkippedLines{'%'})) line_of[static_cast<std::size_t>(i++)] = walk.line_number();
        }
    }
    const int before = num_threads();
    for (int threads : {1, 2, 3, 7}) {
        set_num_threads(threads);
        for (const std::string& t : {text, text.substr(0, text.size() - 6)}) {  // TAIL\n, or the last record without '\n'
            TextReader r("t.txt", t);
            ASSERT_TRUE(r.next_line());
            const auto block = split_record_lines(r, n, SkippedLines{'%'}, 1000);
            ASSERT_TRUE(block) << threads;
            if (threads > 1) {
                EXPECT_GT(block->chunks.size(), 20u);  // not one chunk per thread
            }
            std::int64_t seen = 0;
            for (const RecordChunk& c : block->chunks) {
                ASSERT_EQ(c.first, seen);
                EXPECT_GT(c.count, 0);
                EXPECT_TRUE(for_each_record_line(
                    r.content(), c, SkippedLines{'%'}, [&](std::string_view line, std::int64_t record, std::size_t number) {
                        EXPECT_EQ(record, seen);
                        EXPECT_EQ(line, std::to_string(record) + " " + std::to_string(2 * record));
                        EXPECT_EQ(number, line_of[static_cast<std::size_t>(record)]);
                        ++seen;
                        return true;
                    }));
            }
            ASSERT_EQ(seen, n) << threads;
            EXPECT_EQ(block->last_line, line_of.back());
            r.seek(block->end, block->last_line);
            EXPECT_EQ(r.line(), std::to_string(n - 1) + " " + std::to_string(2 * (n - 1)));
            EXPECT_EQ(r.next_nonblank_line(), t.size() == text.size()) << threads;
        }
        // One record more than the content holds.
        TextReader short_reader("t.txt", text);
        short_reader.next_line();
        EXPECT_FALSE(split_record_lines(short_reader, n + 2, SkippedLines{'%'}, 1000)) << threads;  // TAIL is one
        TextReader exact("t.txt", text);
        exact.next_line();
        EXPECT_TRUE(split_record_lines(exact, n + 1, SkippedLines{'%'}, 1000)) << threads;
    }
    set_num_threads(before);
}

namespace {

// A 2D SU2 strip of 2 × n quadrilaterals (3 × (n + 1) points), with blank and
// comment lines inside its blocks: several chunks of 4096 records.
std::string strip_su2(int n, std::string_view bad_cell = {}, int bad_at = -1) {
    std::string s = "NDIME= 2\nNELEM= " + std::to_string(2 * n) + "\n";
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2; ++j) {
            const int a = i * 3 + j;
            if (2 * i + j == bad_at)
                s += std::string(bad_cell) + "\n";
            else
                s += "9 " + std::to_string(a) + " " + std::to_string(a + 3) + " " + std::to_string(a + 4) + " " +
                     std::to_string(a + 1) + " " + std::to_string(2 * i + j) + "\n";
            if ((2 * i + j) % 1000 == 999) s += "% comment\n\n";
        }
    s += "NPOIN= " + std::to_string(3 * (n + 1)) + "\n";
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j < 3; ++j) s += std::to_string(0.1 * i) + " " + std::to_string(0.5 * j) + "\r\n";
    s += "NMARK= 1\nMARKER_TAG= bottom\nMARKER_ELEMS= " + std::to_string(n) + "\n";
    for (int i = 0; i < n; ++i) s += "3 " + std::to_string(3 * i) + " " + std::to_string(3 * i + 3) + "\n";
    return s;
}

}  // namespace

TEST(RecordLines, Su2BlocksReadOnThreadsGiveTheMeshByConstruction) {
    const int n = 6000;  // 12,000 cells: 3 chunks of 4096
    const int before = num_threads();
    for (int threads : {1, 2, 3}) {
        set_num_threads(threads);
        const Mesh m = read_su2_text("strip.su2", strip_su2(n));
        ASSERT_EQ(m.cells.size(), 2u * n);
        ASSERT_EQ(m.num_points(), 3u * (n + 1));
        for (int c : {0, 4095, 4096, 8191, 8192, 2 * n - 1}) {
            const int i = c / 2, j = c % 2, a = 3 * i + j;
            const std::vector<NodeId> expected = {a, a + 3, a + 4, a + 1};
            const auto nodes = m.cells.nodes_of(static_cast<std::size_t>(c));
            EXPECT_EQ(std::vector<NodeId>(nodes.begin(), nodes.end()), expected) << "cell " << c;
        }
        EXPECT_EQ(m.points[2 * 7000], std::stod(std::to_string(0.1 * (7000 / 3))));
        EXPECT_EQ(m.points[2 * 7000 + 1], 0.5 * (7000 % 3));
        ASSERT_EQ(m.markers.size(), 1u);
        EXPECT_EQ(m.markers[0].elements.size(), static_cast<std::size_t>(n));
    }
    set_num_threads(before);
}

TEST(RecordLines, ABadRecordDeepInABlockIsNamedByItsLine) {
    // Cell 9000 (in the third chunk) with a node id the reader refuses: the
    // error names its line, counting the comment and blank lines before it.
    const int bad = 9000;
    const std::size_t line = 2 + static_cast<std::size_t>(bad) + 1 + 2 * (bad / 1000);
    for (int threads : {1, 2}) {
        const int before = num_threads();
        set_num_threads(threads);
        try {
            read_su2_text("strip.su2", strip_su2(6000, "9 0 1 -2 3 4", bad));
            ADD_FAILURE() << "no error";
        } catch (const ParseError& e) {
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_NE(std::string(e.what()).find("element 9001 of the 12000"), std::string::npos) << e.what();
        }
        set_num_threads(before);
    }
}

TEST(RecordLines, GmshBlocksReadOnThreadsRoundTripAndNameABadLine) {
    const Mesh strip = read_su2_text("strip.su2", strip_su2(6000));
    const auto file = test::scratch_dir() / "strip.msh";
    write_mesh(file, strip);
    const int before = num_threads();
    for (int threads : {1, 2, 3}) {
        set_num_threads(threads);
        const Mesh back = read_mesh(file);
        EXPECT_EQ(back.points, strip.points);
        EXPECT_EQ(back.cells, strip.cells);
    }
    // The element of tag 9000 given a node tag $Nodes does not define: the
    // error names its line (the line-by-line code's message).
    std::string text = read_file_text(file);
    const std::size_t at = text.find("\n9000 ", text.find("$Elements")) + 1;
    ASSERT_NE(at, std::string::npos + 1);
    const std::size_t end = text.find('\n', at);
    const std::size_t last_space = text.rfind(' ', end);
    text.replace(last_space + 1, end - last_space - 1, "999999999");
    const auto line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
    const auto damaged = test::scratch_dir() / "strip-damaged.msh";
    {
        std::ofstream out(damaged, std::ios::binary);
        out << text;
    }
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        try {
            read_mesh(damaged);
            ADD_FAILURE() << "no error";
        } catch (const ParseError& e) {
            EXPECT_EQ(e.line(), line) << e.what();
            EXPECT_NE(std::string(e.what()).find("999999999"), std::string::npos) << e.what();
        }
    }
    set_num_threads(before);
}

TEST(RecordLines, JoinedPartsAreTheListPushedInOrderPolyhedraWithTheirFaces) {
    // A pyramid as a polyhedron (a square and four triangles), between other cells.
    const std::vector<NodeId> rings = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    const std::vector<int> sizes = {4, 3, 3, 3, 3};
    const std::vector<NodeId> tet = {0, 1, 2, 4}, hex = {0, 1, 2, 3, 4, 5, 6, 7};
    ElementList expected;
    std::vector<ElementList> parts(5);
    const auto push = [&](std::size_t part, int what) {
        for (ElementList* l : {&expected, &parts[part]}) {
            if (what == 0) l->push_back(CellType::tetrahedron, tet);
            if (what == 1) l->push_polyhedron(rings, sizes);
            if (what == 2) l->push_back(CellType::hexahedron, hex);
        }
    };
    push(0, 0);
    push(0, 2);
    push(1, 1);  // the first polyhedron: the lists before it get their (empty) faces
    push(1, 0);
    push(3, 2);  // part 2 stays empty
    push(4, 1);
    push(4, 1);
    ElementList joined;
    append_element_parts(joined, parts);
    EXPECT_EQ(joined, expected);
    // Without polyhedra the face arrays stay empty.
    ElementList plain;
    std::vector<ElementList> plain_parts(2);
    plain_parts[0].push_back(CellType::tetrahedron, tet);
    plain_parts[1].push_back(CellType::hexahedron, hex);
    append_element_parts(plain, plain_parts);
    EXPECT_FALSE(plain.has_faces());
    EXPECT_EQ(plain.size(), 2u);
}

namespace {

// "HEAD\n" then n element records "k id..." (k = 3: a triangle, 4: a
// quadrilateral, in turn by threes), the record `bad` (if any) with a token
// the parser below refuses.
std::string element_records(int n, int bad = -1) {
    std::string s = "HEAD\n";
    for (int i = 0; i < n; ++i) {
        const int k = i % 3 == 0 ? 4 : 3;
        s += std::to_string(k);
        for (int j = 0; j < k; ++j) s += " " + (i == bad && j == 1 ? std::string("x") : std::to_string(i + j));
        s += "\n";
    }
    return s;
}

bool parse_element_record(std::string_view line, ElementList& out) {
    LineTokens tokens(line);
    std::int64_t k = 0, id = 0;
    if (!parse_plain_digits(tokens.next(), k) || (k != 3 && k != 4)) return false;
    std::vector<NodeId> nodes;
    for (std::int64_t j = 0; j < k; ++j) {
        if (!parse_plain_digits(tokens.next(), id)) return false;
        nodes.push_back(static_cast<NodeId>(id));
    }
    out.push_back(k == 3 ? CellType::triangle : CellType::quadrilateral, nodes);
    return true;
}

}  // namespace

TEST(RecordLines, ElementsParsedInWavesAreTheListPushedLineByLineAndAFailureLeavesTheListAsItWas) {
    // 200,000 records: 49 chunks of 4096, so two waves or more whatever the thread count.
    const int n = 200000;
    ASSERT_GT(static_cast<std::size_t>(n) / 4096, element_wave_chunks());
    const std::vector<NodeId> tet = {7, 8, 9, 10};
    ElementList expected;
    expected.push_back(CellType::tetrahedron, tet);  // what the list held before the block
    {
        const std::string text = element_records(n);
        TextReader walk("e.txt", text);
        walk.next_line();
        for (int i = 0; i < n; ++i) {
            ASSERT_TRUE(walk.next_line());
            ASSERT_TRUE(parse_element_record(walk.line(), expected));
        }
    }
    const int before = num_threads();
    for (int threads : {1, 2, 3}) {
        set_num_threads(threads);
        for (int bad : {-1, 5, 150000}) {  // none, in the first wave, in a later one
            const std::string text = element_records(n, bad);
            TextReader r("e.txt", text);
            ASSERT_TRUE(r.next_line());
            const auto block = split_record_lines(r, n, SkippedLines{});
            ASSERT_TRUE(block);
            ElementList out;
            out.push_back(CellType::tetrahedron, tet);
            const ElementList held = out;
            const bool ok = parse_element_chunks(r, *block, out, [&](std::size_t c, ElementList& part) {
                EXPECT_TRUE(part.empty());
                return for_each_record_line(r.content(), block->chunks[c], SkippedLines{},
                                            [&](std::string_view line, std::int64_t, std::size_t) {
                                                return parse_element_record(line, part);
                                            });
            });
            EXPECT_EQ(ok, bad < 0) << threads << " threads, bad record " << bad;
            EXPECT_EQ(out, bad < 0 ? expected : held) << threads << " threads, bad record " << bad;
        }
    }
    set_num_threads(before);
    // A list with polyhedra before the block, cut back as it was.
    const std::vector<NodeId> rings = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    const std::vector<int> sizes = {4, 3, 3, 3, 3};
    ElementList with_faces;
    with_faces.push_polyhedron(rings, sizes);
    const ElementList held = with_faces;
    const ElementListSizes at = sizes_of(with_faces);
    with_faces.push_back(CellType::tetrahedron, tet);
    with_faces.push_polyhedron(rings, sizes);
    restore_sizes(with_faces, at);
    EXPECT_EQ(with_faces, held);
}
