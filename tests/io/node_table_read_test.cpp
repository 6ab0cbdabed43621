#include "dgwarp/io/node_table_read.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "dgwarp/core/error.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const auto path = test::scratch_dir() / name;
    std::ofstream(path) << text;
    return path;
}

/// The ParseError thrown by f(), or fails the test.
template <class F>
ParseError parse_error_of(F f) {
    try {
        f();
    } catch (const ParseError& e) {
        return e;
    }
    ADD_FAILURE() << "no ParseError";
    return ParseError("", 0, "", "");
}

}  // namespace

TEST(MotionNodeFiles, DisplacementCsvWithHeader) {
    const auto path = write_file("d.csv", "node,dx,dy\n4, 0.5, -1\n7,1e-3,2\n");
    const auto t = read_displacement_csv(path);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.source, path.string());
    EXPECT_EQ(t.nodes, (std::vector<NodeId>{4, 7}));
    EXPECT_EQ(t.values[0], (Vec3{0.5, -1, 0}));
    EXPECT_EQ(t.values[1], (Vec3{1e-3, 2, 0}));
    EXPECT_EQ(t.lines, (std::vector<std::size_t>{2, 3}));
}

TEST(MotionNodeFiles, DisplacementCsvWithoutHeaderBlanksAndComments) {
    const auto path = write_file("d.csv", "# bump\n\n0,1,2,3\r\n  \n% note\n2,4,5,6\n");
    const auto t = read_displacement_csv(path);
    EXPECT_EQ(t.components, 3);
    EXPECT_EQ(t.nodes, (std::vector<NodeId>{0, 2}));
    EXPECT_EQ(t.values[1], (Vec3{4, 5, 6}));
    EXPECT_EQ(t.lines, (std::vector<std::size_t>{3, 6}));
}

TEST(MotionNodeFiles, DisplacementCsvBadLinesNameFileAndLine) {
    struct Case {
        std::string text;
        std::size_t line;
        std::string found;
    };
    const Case cases[] = {
        {"node,dx,dy\n1,2,3\n2,x,3\n", 3, "x"},              // not a number
        {"1,2,3\n2,nan,3\n", 2, "nan"},                       // NaN
        {"1,2,3\n2,inf,3\n", 2, "inf"},                       // infinity
        {"1,2,3\n2,3\n", 2, "2 fields: 2,3"},                 // fewer fields than line 1
        {"1,2,3\n2,3,4,5\n", 2, "4 fields: 2,3,4,5"},         // more fields than line 1
        {"1,2\n", 1, "2 fields: 1,2"},                        // too few for any form
        {"1,2,3\n-4,1,1\n", 2, "-4"},                         // negative node id
        {"1,2,3\n2.5,1,1\n", 2, "2.5"},                       // fractional node id
        {"1,2,3\n4,,1\n", 2, ""},                             // empty field
        {"node,dx,dy\nnode,dx,dy\n", 2, "node"},              // a second header
        {"1,2,3\n1,2,4\n", 2, "other values"},                // same node, other values
    };
    for (const Case& c : cases) {
        const auto path = write_file("bad.csv", c.text);
        const ParseError e = parse_error_of([&] { read_displacement_csv(path); });
        EXPECT_EQ(e.file(), path.string()) << c.text;
        EXPECT_EQ(e.line(), c.line) << c.text;
        EXPECT_EQ(e.found(), c.found) << c.text;
    }
}

TEST(MotionNodeFiles, EmptyFileAndMissingFile) {
    const auto path = write_file("empty.csv", "node,dx,dy\n\n");
    EXPECT_EQ(parse_error_of([&] { read_displacement_csv(path); }).found(), "end of file");
    EXPECT_THROW(read_displacement_csv(path.parent_path() / "none.csv"), IoError);
}

TEST(MotionNodeFiles, RepeatedNodeWithSameValuesIsKeptOnce) {
    const auto path = write_file("d.csv", "3,1,2\n5,0,0\n3,1,2\n3,1,2\n");
    const auto t = read_displacement_csv(path);
    EXPECT_EQ(t.nodes, (std::vector<NodeId>{3, 5}));
    EXPECT_EQ(t.lines, (std::vector<std::size_t>{1, 2}));
}

TEST(MotionNodeFiles, Su2SurfaceFile) {
    // The form SU2_DEF writes for DV_KIND= SURFACE_FILE: global index, then x y [z], tab separated.
    const auto path = write_file("surface_positions.dat", "0\t1.5\t0.25\n12\t-3\t4e-2\n");
    const auto t = read_su2_surface_file(path);
    EXPECT_EQ(t.components, 2);
    EXPECT_EQ(t.nodes, (std::vector<NodeId>{0, 12}));
    EXPECT_EQ(t.values[1], (Vec3{-3, 0.04, 0}));

    const auto path3 = write_file("s3.dat", "7 1 2 3\n8 4 5 6\n");
    EXPECT_EQ(read_su2_surface_file(path3).components, 3);

    // No header line in SU2's form.
    const auto bad = write_file("s.dat", "id x y\n1 2 3\n");
    const ParseError e = parse_error_of([&] { read_su2_surface_file(bad); });
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.found(), "id");
}

TEST(MotionNodeFiles, NodeMotionCsvBothForms) {
    const auto path = write_file("m.csv", "node,tx,ty,tz,wx,wy,wz,cx,cy,cz\n9,1,2,3,0.1,0.2,0.3,4,5,6\n");
    const auto t = read_node_motion_csv(path);
    EXPECT_EQ(t.components, 3);
    ASSERT_EQ(t.nodes, (std::vector<NodeId>{9}));
    EXPECT_EQ(t.values[0].translation, (Vec3{1, 2, 3}));
    EXPECT_EQ(t.values[0].rotation, (Vec3{0.1, 0.2, 0.3}));
    EXPECT_EQ(t.values[0].center, (Vec3{4, 5, 6}));

    const auto path2 = write_file("m2.csv", "node,tx,ty,wz,cx,cy\n3,1,2,0.5,4,5\n");
    const auto t2 = read_node_motion_csv(path2);
    EXPECT_EQ(t2.components, 2);
    EXPECT_EQ(t2.values[0].translation, (Vec3{1, 2, 0}));
    EXPECT_EQ(t2.values[0].rotation, (Vec3{0, 0, 0.5}));
    EXPECT_EQ(t2.values[0].center, (Vec3{4, 5, 0}));

    const auto bad = write_file("m3.csv", "3,1,2,0.5\n");
    EXPECT_EQ(parse_error_of([&] { read_node_motion_csv(bad); }).line(), 1u);
}
