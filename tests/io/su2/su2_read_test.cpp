#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "support/mesh_file_test_name.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

// The spec: ../shared/meshes/README.md beside the repository. Cell types are
// the README's where it names them ("tri", "pyr+tet", ...); for the other rows
// they were counted with awk on the files' NELEM sections.
struct ExpectedMesh {
    std::string file;
    int dim;
    std::size_t nodes;
    std::size_t cells;
    std::vector<std::string> markers;
    std::set<CellType> cell_types;
};

const std::vector<std::string> brick_markers = {"x_m", "x_p", "y_m", "y_p", "z_m", "z_p"};
constexpr auto tri = CellType::triangle, quad = CellType::quadrilateral, tet = CellType::tetrahedron,
               hex = CellType::hexahedron, prism = CellType::prism, pyr = CellType::pyramid;

const std::string cht_file = "incomp_navierstokes_streamwise_periodic_chtPinArray_3d_3D_chtPinArray_coarse.su2";
const std::vector<std::string> cht_zone1_markers = {
    "fluid_bottom_interface", "fluid_pin1", "fluid_pin2",  "fluid_pin3",
    "fluid_top",              "fluid_inlet", "fluid_outlet", "fluid_sym_sides"};
const std::vector<std::string> cht_zone2_markers = {
    "solid_bottom_interface", "solid_pin1",        "solid_pin2",       "solid_pin3",
    "solid_sym_sides",        "solid_pins_top",    "solid_bottom_heater", "solid_pin3_outlet",
    "solid_pin1_inlet",       "solid_block_inlet", "solid_block_outlet"};

const std::vector<ExpectedMesh>& expected_meshes() {
    static const std::vector<ExpectedMesh> table = {
        {"deformation_naca0012_mesh_NACA0012_inv.su2", 2, 5233, 10216, {"airfoil", "farfield"}, {tri}},
        {"aeroelastic_mesh_NACA64A010_hybrid_inv.su2", 2, 6532, 9313, {"airfoil", "farfield"}, {tri, quad}},
        {"unsteady_pitching_naca64a010_rans_mesh_NACA64A010_turb.su2", 2, 24111, 35404, {"airfoil", "farfield"},
         {tri, quad}},
        {"deformation_rae2822_mesh_RAE2822_turb_ffd.su2", 2, 13937, 22842, {"AIRFOIL", "FARFIELD"}, {tri, quad}},
        {"rans_naca0012_n0012_225-65.su2", 2, 14576, 14336, {"airfoil", "farfield"}, {quad}},
        {"unsteady_square_cylinder_mesh_square_turb_hybrid.su2", 2, 18780, 23085,
         {"inlet", "lower", "outlet", "square", "upper"}, {tri, quad}},
        {"fea_fsi_Airfoil_RBF_meshFlow.su2", 2, 15504, 15300,
         {"farfield", "leading_edge", "suction_side", "pressure_side"}, {quad}},
        {"deformation_brick_hex_mesh_brick_hex_ffd.su2", 3, 16000, 14079, brick_markers, {hex}},
        {"deformation_brick_prism_mesh_brick_prism_ffd.su2", 3, 16800, 29640, brick_markers, {prism}},
        {"deformation_brick_pyra_mesh_brick_pyra_ffd.su2", 3, 14030, 72625, brick_markers, {pyr, tet}},
        {"deformation_brick_tets_mesh_brick_tets_ffd.su2", 3, 11703, 59156, brick_markers, {tet}},
        {cht_file, 3, 10800, 9063, cht_zone1_markers, {hex}},  // zone 1
    };
    return table;
}

const ExpectedMesh* find_expected(const std::string& file) {
    for (const ExpectedMesh& e : expected_meshes())
        if (e.file == file) return &e;
    return nullptr;
}

std::vector<std::string> marker_names(const Mesh& m) {
    std::vector<std::string> names;
    for (const Marker& marker : m.markers) names.push_back(marker.name);
    return names;
}

std::set<CellType> cell_types(const Mesh& m) { return {m.cells.types.begin(), m.cells.types.end()}; }

void expect_counts(const Mesh& m, const ExpectedMesh& e) {
    EXPECT_EQ(m.dim, e.dim);
    EXPECT_EQ(m.num_points(), e.nodes);
    EXPECT_EQ(m.cells.size(), e.cells);
    EXPECT_EQ(marker_names(m), e.markers);
    EXPECT_EQ(cell_types(m), e.cell_types);
}

// Every node of a boundary element is a node of some volume cell.
void expect_markers_on_cells(const Mesh& m) {
    std::vector<bool> in_cell(m.num_points(), false);
    for (NodeId n : m.cells.nodes) in_cell[static_cast<std::size_t>(n)] = true;
    for (const Marker& marker : m.markers)
        for (NodeId n : marker.elements.nodes) ASSERT_TRUE(in_cell[static_cast<std::size_t>(n)]) << marker.name << " " << n;
}

}  // namespace

TEST(Su2Meshes, TheFolderHoldsExactlyTheMeshesOfTheReadme) {
    DGWARP_REQUIRE_SHARED_MESHES();
    std::set<std::string> found, expected;
    for (const auto& p : test::su2_meshes()) found.insert(p.filename().string());
    for (const ExpectedMesh& e : expected_meshes()) expected.insert(e.file);
    EXPECT_EQ(found, expected);
}

class Su2ReadRealMesh : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(Su2ReadRealMesh, CountsMatchTheReadmeAndTheMeshIsValid) {
    const ExpectedMesh* e = find_expected(GetParam().filename().string());
    ASSERT_NE(e, nullptr) << GetParam() << " is not in the README table";
    const Mesh m = read_su2(GetParam());
    expect_counts(m, *e);
    EXPECT_NO_THROW(validate(m));
    expect_markers_on_cells(m);
    for (const Marker& marker : m.markers) EXPECT_FALSE(marker.elements.empty()) << marker.name;
}

INSTANTIATE_TEST_SUITE_P(Su2, Su2ReadRealMesh, testing::ValuesIn(test::su2_meshes()), test::mesh_file_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Su2ReadRealMesh);

TEST(Su2ReadRealMeshValues, FirstAndLastRecordsAreTheFilesText) {
    DGWARP_REQUIRE_SHARED_MESHES();
    // Values copied from the files' text.
    const Mesh a = read_su2(test::su2_meshes_dir() / "deformation_naca0012_mesh_NACA0012_inv.su2");
    EXPECT_EQ(a.points[0], 9.997500181200000e-01);
    EXPECT_EQ(a.points[1], -3.632896519016437e-05);
    EXPECT_EQ(std::vector<NodeId>(a.cells.nodes_of(0).begin(), a.cells.nodes_of(0).end()),
              (std::vector<NodeId>{417, 69, 311}));
    EXPECT_EQ(std::vector<NodeId>(a.cells.nodes_of(10215).begin(), a.cells.nodes_of(10215).end()),
              (std::vector<NodeId>{5122, 5109, 5075}));

    // "NDIME=2" without a space, " \t " separators, Fortran-style exponents.
    const Mesh b = read_su2(test::su2_meshes_dir() / "rans_naca0012_n0012_225-65.su2");
    EXPECT_EQ(b.points[0], 501.000007802345);
    EXPECT_EQ(b.points[1], 5.352202629500000E-008);
    EXPECT_EQ(b.cells.types[0], CellType::quadrilateral);
    EXPECT_EQ(std::vector<NodeId>(b.cells.nodes_of(0).begin(), b.cells.nodes_of(0).end()),
              (std::vector<NodeId>{0, 1, 177, 176}));

    // 3D with tabs and a pyramid as last cell: "14 59 58 57 799 4428 72624".
    const Mesh c = read_su2(test::su2_meshes_dir() / "deformation_brick_pyra_mesh_brick_pyra_ffd.su2");
    ASSERT_EQ(c.cells.types.back(), CellType::pyramid);
    EXPECT_EQ(std::vector<NodeId>(c.cells.nodes_of(72624).begin(), c.cells.nodes_of(72624).end()),
              (std::vector<NodeId>{59, 58, 57, 799, 4428}));
    EXPECT_EQ(c.points[3], 5.128205128205128e-02);
}

TEST(Su2ReadZones, BothZonesOfTheChtFileReadWithTheReadmeCounts) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto path = test::su2_meshes_dir() / cht_file;
    const Mesh z1 = read_su2(path, 1);
    const Mesh z2 = read_su2(path, 2);
    expect_counts(z1, {cht_file, 3, 10800, 9063, cht_zone1_markers, {hex}});
    expect_counts(z2, {cht_file, 3, 17136, 14513, cht_zone2_markers, {hex}});
    EXPECT_NO_THROW(validate(z1));
    EXPECT_NO_THROW(validate(z2));
    expect_markers_on_cells(z2);
    // First cell of zone 2: "12 3044 591 31 462 7692 3205 534 2966 0".
    EXPECT_EQ(std::vector<NodeId>(z2.cells.nodes_of(0).begin(), z2.cells.nodes_of(0).end()),
              (std::vector<NodeId>{3044, 591, 31, 462, 7692, 3205, 534, 2966}));
    EXPECT_EQ(read_su2(path), z1);
}

TEST(Su2ReadZones, AnAbsentZoneNamesTheFileTheZoneAndTheZoneCount) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto path = test::su2_meshes_dir() / cht_file;
    try {
        read_su2(path, 3);
        FAIL() << "zone 3 was read";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), path.string());
        EXPECT_EQ(e.line(), 2u);  // NZONE= 2
        const std::string what = e.what();
        EXPECT_NE(what.find("zone 3"), std::string::npos) << what;
        EXPECT_NE(what.find("2 zones"), std::string::npos) << what;
    }
    EXPECT_THROW(read_su2(path, 0), ParseError);
}

TEST(Su2ReadZones, ASingleZoneFileHasOnlyZoneOne) {
    const std::string text = "NDIME= 2\nNELEM= 1\n5 0 1 2\nNPOIN= 3\n0 0\n1 0\n0 1\nNMARK= 0\n";
    EXPECT_NO_THROW(read_su2_text("one.su2", text, 1));
    try {
        read_su2_text("one.su2", text, 2);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "one.su2");
        EXPECT_NE(std::string(e.what()).find("single zone"), std::string::npos) << e.what();
    }
}

TEST(Su2ReadZones, AZoneMissingFromAFileThatAnnouncesItIsAParseError) {
    const std::string text = "NZONE= 3\nIZONE= 1\nNDIME= 2\nNELEM= 0\nNPOIN= 0\nNMARK= 0\n"
                             "IZONE= 2\nNDIME= 2\nNELEM= 1\n5 0 1 2\nNPOIN= 3\n1 2\n3 4\n5 7\nNMARK= 0\n";
    EXPECT_EQ(read_su2_text("z.su2", text, 2).num_points(), 3u);
    try {
        read_su2_text("z.su2", text, 3);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 15u);
        EXPECT_EQ(e.found(), "end of file");
        EXPECT_NE(e.expected().find("IZONE= 3"), std::string::npos) << e.what();
    }
}

TEST(Su2ReadZones, AZoneWithoutCellsIsAParseErrorAtItsNelem) {
    // Issue #27: a 0-cell mesh was read, measured (min quality 0 of cell -1)
    // and written to .vtu/.msh files that dgwarp then refused.
    try {
        read_su2_text("empty.su2", "NDIME= 2\nNELEM= 0\nNPOIN= 1\n0 0\nNMARK= 0\n");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 2u);
        EXPECT_EQ(e.found(), "0");
        EXPECT_NE(e.expected().find("a positive element count"), std::string::npos) << e.what();
    }
}

TEST(Su2ReadText, Hand2DWithTabsCommentsCrlfTrailingColumnsAndFfd) {
    const std::string text =
        "%\r\n% a 2D mesh: a quad and two triangles\r\n%\r\n"
        "NDIME=2\r\n"
        "NELEM=3\r\n"
        "9\t0\t1\t4\t3\t0\r\n"
        "5 1 2 5 1\r\n"
        "  5\t 1   5 4   2  \r\n"
        "% points, some with extra columns\r\n"
        "NPOIN= 6 6\r\n"
        "0 0 0\r\n"
        "1\t0\t1\r\n"
        "2.5e0 0 2 7 8\r\n"
        "\t0\t1\t3\r\n"
        "1 1.0\r\n"
        "2 1 5\r\n"
        "\r\n"
        "NMARK= 2\r\n"
        "MARKER_TAG= lower\r\n"
        "MARKER_ELEMS= 2\r\n"
        "3 0 1\r\n"
        "3\t1\t2\t99\r\n"
        "MARKER_TAG=corner\r\n"
        "MARKER_ELEMS=1\r\n"
        "1 5\r\n"
        "NPERIODIC= 1\r\n"
        "PERIODIC_INDEX= 0\r\n"
        "0 0 0\r\n"
        "FFD_NBOX= 1\r\n"
        "FFD_TAG= MAIN_BOX\r\n"
        "FFD_CORNER_POINTS= 4\r\n"
        "0 0\r\n1 0\r\n1 1\r\n0 1\r\n"
        "FFD_SURFACE_POINTS= 1\r\n"
        "lower\t0\t0.5\t0.5\r\n";
    const Mesh m = read_su2_text("hand2d.su2", text);
    Mesh expected;
    expected.dim = 2;
    expected.points = {0, 0, 1, 0, 2.5, 0, 0, 1, 1, 1, 2, 1};
    const NodeId q[] = {0, 1, 4, 3}, t0[] = {1, 2, 5}, t1[] = {1, 5, 4};
    expected.cells.push_back(CellType::quadrilateral, q);
    expected.cells.push_back(CellType::triangle, t0);
    expected.cells.push_back(CellType::triangle, t1);
    Marker lower{"lower", {}}, corner{"corner", {}};
    const NodeId l0[] = {0, 1}, l1[] = {1, 2}, v[] = {5};
    lower.elements.push_back(CellType::line, l0);
    lower.elements.push_back(CellType::line, l1);
    corner.elements.push_back(CellType::vertex, v);
    expected.markers = {lower, corner};
    EXPECT_EQ(m, expected);
}

TEST(Su2ReadText, ElementTokensBeyondPlainDigitsReadAsPlainOnes) {
    // Each cell line in another form (signs, leading zeros, 19 digits, CR
    // and form feeds as blanks, a last token without a line end): the same
    // mesh as the plain lines, from the records' fast path and its token path alike.
    const std::string points = "NPOIN= 6\n0 0\n1 0\n2 0\n0 1\n1 1\n2 1\n";
    const std::string marker = "NMARK= 1\nMARKER_TAG= lower\nMARKER_ELEMS= 1\n3 0 1";
    const Mesh plain = read_su2_text("plain.su2", "NDIME= 2\nNELEM= 4\n5 0 1 4\n5 0 4 3 1\n5 1 2 5\n5 1 5 4\n" +
                                                      points + marker + "\n");
    const Mesh forms =
        read_su2_text("forms.su2", "NDIME= 2\nNELEM= 4\n+5 00 +1 0004\n5\f0\v4\t3 +1\r\n"
                                   "5 0000000000000000001 2 00000000000000000005\n005 1 5 +4 99999999999999999999\n" +
                                       points + marker);
    EXPECT_EQ(forms, plain);
    // A token of digits run into other characters is refused, as before.
    EXPECT_THROW(read_su2_text("bad.su2", "NDIME= 2\nNELEM= 1\n5 0 1x 4\n" + points + marker), ParseError);
    EXPECT_THROW(read_su2_text("bad.su2", "NDIME= 2\nNELEM= 1\n5 0 1 4.0\n" + points + marker), ParseError);
    // A run of digits longer than any id (read without overflow: the fuzzer's find).
    EXPECT_THROW(read_su2_text("bad.su2", "NDIME= 2\nNELEM= 1\n5 0 1 " + std::string(40, '7') + "\n" + points + marker),
                 ParseError);
}

TEST(Su2ReadText, Hand3DWithAllVolumeCellTypes) {
    const std::string text =
        "NDIME= 3\n"
        "NELEM= 4\n"
        "12 0 1 2 3 4 5 6 7 0\n"
        "14 4 5 6 7 8 1\n"
        "10 4 5 7 8 2\n"
        "13 0 1 2 4 5 6 3\n"
        "NPOIN= 9\n"
        "0 0 0 0\n1 0 0 1\n1 1 0 2\n0 1 0 3\n"
        "0 0 1 4\n1 0 1 5\n1 1 1 6\n0 1 1 7\n"
        "0.5 0.5 2 8\n"
        "NMARK= 2\n"
        "MARKER_TAG= bottom\n"
        "MARKER_ELEMS= 1\n"
        "9 0 3 2 1\n"
        "MARKER_TAG= top\n"
        "MARKER_ELEMS= 2\n"
        "5 4 5 8\n"
        "5 5 6 8\n"
        "FFD_NBOX= 1\n"
        "FFD_NLEVEL= 1\n";
    const Mesh m = read_su2_text("hand3d.su2", text);
    Mesh expected;
    expected.dim = 3;
    expected.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 2};
    const NodeId h[] = {0, 1, 2, 3, 4, 5, 6, 7}, p[] = {4, 5, 6, 7, 8}, t[] = {4, 5, 7, 8}, w[] = {0, 1, 2, 4, 5, 6};
    expected.cells.push_back(CellType::hexahedron, h);
    expected.cells.push_back(CellType::pyramid, p);
    expected.cells.push_back(CellType::tetrahedron, t);
    expected.cells.push_back(CellType::prism, w);
    Marker bottom{"bottom", {}}, top{"top", {}};
    const NodeId b[] = {0, 3, 2, 1}, t0[] = {4, 5, 8}, t1[] = {5, 6, 8};
    bottom.elements.push_back(CellType::quadrilateral, b);
    top.elements.push_back(CellType::triangle, t0);
    top.elements.push_back(CellType::triangle, t1);
    expected.markers = {bottom, top};
    EXPECT_EQ(m, expected);
}

TEST(Su2ReadText, SectionsInAnotherOrderAndUnknownSectionsBeforeThem) {
    const std::string text =
        "NDIME= 2\nMY_NOTE= 2\n1 2 3\nabc\nNPOIN= 3\n0 0\n1 0\n0 1\nNMARK= 0\nNELEM= 1\n5 0 1 2\n";
    const Mesh m = read_su2_text("order.su2", text);
    EXPECT_EQ(m.num_points(), 3u);
    EXPECT_EQ(m.cells.size(), 1u);
    EXPECT_TRUE(m.markers.empty());
}

TEST(Su2ReadText, AMissingFileIsAnIoError) {
    EXPECT_THROW(read_su2(test::scratch_dir() / "absent.su2"), IoError);
}
