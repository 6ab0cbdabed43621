#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "support/mesh_file_test_name.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::slurp;

namespace {


std::size_t files_in(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(
        std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
}

/// Two triangles and a vertex marker, with coordinates that have no short
/// decimal form.
Mesh awkward_2d_mesh() {
    Mesh m;
    m.dim = 2;
    m.points = {0.1, 1.0 / 3.0, -2.0 / 7.0, 1e-300, 5e-324, std::numeric_limits<double>::max(),
                -123456.789, 0.30000000000000004};
    const NodeId t0[] = {0, 1, 2}, t1[] = {0, 2, 3};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    Marker wall{"wall", {}}, tip{"tip point", {}};
    const NodeId e0[] = {0, 1}, e1[] = {1, 2}, v[] = {3};
    wall.elements.push_back(CellType::line, e0);
    wall.elements.push_back(CellType::line, e1);
    tip.elements.push_back(CellType::vertex, v);
    m.markers = {wall, tip};
    return m;
}

}  // namespace

TEST(Su2Write, LayoutIsSu2sOwn) {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 0.5, 1.25};
    const NodeId t[] = {0, 1, 2}, e[] = {0, 1};
    m.cells.push_back(CellType::triangle, t);
    Marker wall{"wall", {}};
    wall.elements.push_back(CellType::line, e);
    m.markers = {wall};
    std::ostringstream out;
    write_su2(out, m);
    EXPECT_EQ(out.str(),
              "NDIME= 2\n"
              "NELEM= 1\n"
              "5\t0\t1\t2\t0\n"
              "NPOIN= 3\n"
              "0\t0\t0\n"
              "1\t0\t1\n"
              "0.5\t1.25\t2\n"
              "NMARK= 1\n"
              "MARKER_TAG= wall\n"
              "MARKER_ELEMS= 1\n"
              "3\t0\t1\n");
}

TEST(Su2Write, RoundTripIsBitExact) {
    const Mesh m = awkward_2d_mesh();
    std::ostringstream out;
    write_su2(out, m);
    const Mesh back = read_su2_text("awkward.su2", out.str());
    EXPECT_EQ(back, m);
    ASSERT_EQ(back.points.size(), m.points.size());
    EXPECT_EQ(std::memcmp(back.points.data(), m.points.data(), m.points.size() * sizeof(double)), 0);
}

TEST(Su2Write, AMeshWithoutCellsIsRefusedBeforeWriting) {
    // It used to round-trip; no reader but SU2's took it back, and nothing
    // can be measured or deformed on it (issue #27): validate() refuses it.
    Mesh m;
    m.dim = 3;
    std::ostringstream out;
    EXPECT_THROW(write_su2(out, m), MeshError);
    EXPECT_EQ(out.str(), "");
}

class Su2WriteRealMesh : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(Su2WriteRealMesh, WriteThenReadGivesTheSameMesh) {
    const Mesh m = read_su2(GetParam());
    const auto file = test::scratch_dir() / GetParam().filename();
    write_su2(file, m);
    const Mesh back = read_su2(file);
    EXPECT_TRUE(back == m);  // not EXPECT_EQ: printing a whole mesh on failure helps no one
    EXPECT_EQ(back.num_points(), m.num_points());
    EXPECT_EQ(back.cells.size(), m.cells.size());
}

INSTANTIATE_TEST_SUITE_P(Su2, Su2WriteRealMesh, testing::ValuesIn(test::su2_meshes()), test::mesh_file_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Su2WriteRealMesh);

TEST(Su2Write, SecondZoneOfTheChtFileRoundTrips) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto path =
        test::su2_meshes_dir() / "incomp_navierstokes_streamwise_periodic_chtPinArray_3d_3D_chtPinArray_coarse.su2";
    const Mesh m = read_su2(path, 2);
    const auto file = test::scratch_dir() / "zone2.su2";
    write_su2(file, m);
    EXPECT_TRUE(read_su2(file) == m);
}

TEST(Su2Write, AFailedWriteLeavesTheExistingFileIntact) {
    const auto dir = test::scratch_dir();
    const auto file = dir / "mesh.su2";
    write_su2(file, awkward_2d_mesh());
    const std::string before = slurp(file);

    Mesh bad = awkward_2d_mesh();
    bad.cells.nodes[4] = 1000;  // node id out of range
    EXPECT_THROW(write_su2(file, bad), MeshError);
    EXPECT_EQ(slurp(file), before);
    EXPECT_EQ(files_in(dir), 1u);  // no temporary file left behind

    Mesh unnamed = awkward_2d_mesh();
    unnamed.markers[1].name = "";
    EXPECT_THROW(write_su2(file, unnamed), MeshError);
    EXPECT_EQ(slurp(file), before);
    EXPECT_EQ(files_in(dir), 1u);
}

TEST(Su2Write, WritingIntoAMissingFolderIsAnIoError) {
    const auto file = test::scratch_dir() / "no" / "such" / "folder" / "mesh.su2";
    EXPECT_THROW(write_su2(file, awkward_2d_mesh()), IoError);
    EXPECT_FALSE(std::filesystem::exists(file.parent_path()));
}

TEST(Su2Write, MarkerNamesThatCannotBeStoredAreRejected) {
    for (const std::string name : {"", " padded", "padded\t", "two\nlines", "cr\r"}) {
        Mesh m = awkward_2d_mesh();
        m.markers[0].name = name;
        std::ostringstream out;
        try {
            write_su2(out, m);
            ADD_FAILURE() << "accepted marker name '" << name << "'";
        } catch (const MeshError& e) {
            EXPECT_EQ(e.marker(), name);
            EXPECT_EQ(e.index(), 0);
        }
        EXPECT_TRUE(out.str().empty());  // checked before anything is written
    }
    Mesh twice = awkward_2d_mesh();
    twice.markers[1].name = "wall";
    std::ostringstream out;
    EXPECT_THROW(write_su2(out, twice), MeshError);
}

TEST(Su2Write, MeshIoChoosesSu2ByExtension) {
    const auto file = test::scratch_dir() / "by_extension.SU2";
    write_mesh(file, awkward_2d_mesh());
    EXPECT_EQ(read_mesh(file), awkward_2d_mesh());
    EXPECT_EQ(slurp(file).rfind("NDIME= 2\n", 0), 0u);
}
