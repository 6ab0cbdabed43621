// Reading CGNS files: those the CGNS project's converters wrote (tests/data/cgns),
// and the cases they do not make (several zones, vertex BCs, families, MIXED
// sections, structured zones, bad content) written here with libcgns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "io/cgns/cgns_test_support.hpp"
#include "support/cgns_test_writer.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

/// Every element of `list` as (type, nodes), sorted: the elements regardless of their order.
std::vector<std::pair<CellType, std::vector<NodeId>>> cgns_sorted_elements(const ElementList& list) {
    std::vector<std::pair<CellType, std::vector<NodeId>>> all;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const auto n = list.nodes_of(i);
        all.push_back({list.types[i], {n.begin(), n.end()}});
    }
    std::sort(all.begin(), all.end());
    return all;
}

/// The Gmsh mesh the committed mixed.cgns was made from (sources/README).
Mesh cgns_source_mixed() { return read_gmsh(cgns_data("sources/mixed.msh")); }

/// A zone holding the cells `cells` of `mesh` (3D), its vertices the nodes
/// they use in increasing order; `vertex_of` gets the zone vertex (1-based) of each mesh node used.
TestZone cgns_zone_of(const Mesh& mesh, const std::vector<std::size_t>& cells, const std::string& name,
                      std::map<NodeId, cgns_size>& vertex_of) {
    std::set<NodeId> used;
    for (std::size_t c : cells)
        for (NodeId v : mesh.cells.nodes_of(c)) used.insert(v);
    TestZone z;
    z.name = name;
    for (NodeId v : used) {
        vertex_of[v] = static_cast<cgns_size>(z.x.size()) + 1;
        z.x.push_back(mesh.points[3 * static_cast<std::size_t>(v)]);
        z.y.push_back(mesh.points[3 * static_cast<std::size_t>(v) + 1]);
        z.z.push_back(mesh.points[3 * static_cast<std::size_t>(v) + 2]);
    }
    TestSection s{"Cells", cgns_code::MIXED, static_cast<cgns_size>(cells.size()), {}};
    const int prism[] = {0, 2, 1, 3, 5, 4};
    for (std::size_t c : cells) {
        const CellType t = mesh.cells.types[c];
        const auto nodes = mesh.cells.nodes_of(c);
        s.connectivity.push_back(t == CellType::tetrahedron ? cgns_code::TETRA_4
                                 : t == CellType::pyramid   ? cgns_code::PYRA_5
                                 : t == CellType::prism     ? cgns_code::PENTA_6
                                                            : cgns_code::HEXA_8);
        for (std::size_t i = 0; i < nodes.size(); ++i)
            s.connectivity.push_back(vertex_of[nodes[t == CellType::prism ? static_cast<std::size_t>(prism[i]) : i]]);
    }
    z.sections.push_back(s);
    return z;
}

/// The corner coordinates of each cell, in cell order: the cells' geometry whatever the point numbering.
std::vector<std::vector<double>> cgns_cell_corners(const Mesh& mesh) {
    std::vector<std::vector<double>> corners;
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        std::vector<double> x;
        for (NodeId v : mesh.cells.nodes_of(c))
            for (int a = 0; a < mesh.dim; ++a) x.push_back(mesh.points[static_cast<std::size_t>(v * mesh.dim + a)]);
        corners.push_back(x);
    }
    return corners;
}

/// One-cell 3D zone: a tetrahedron, its base triangle a face section "base".
TestZone cgns_tet_zone() {
    TestZone z;
    z.x = {0, 1, 0, 0};
    z.y = {0, 0, 1, 0};
    z.z = {0, 0, 0, 1};
    z.sections = {{"Cells", cgns_code::TETRA_4, 1, {1, 2, 3, 4}}, {"base", cgns_code::TRI_3, 1, {1, 3, 2}}};
    return z;
}

/// 2D: a unit square of two triangles and a quadrilateral to its right, in
/// one MIXED section with four bars; a section "top" of two more bars.
TestZone cgns_square_zone() {
    TestZone z;
    z.x = {0, 1, 1, 0, 2, 2};
    z.y = {0, 0, 1, 1, 0, 1};
    z.sections = {{"All", cgns_code::MIXED, 7,
                   {cgns_code::TRI_3, 1, 2, 3, cgns_code::TRI_3, 1, 3, 4, cgns_code::QUAD_4, 2, 5, 6, 3,
                    cgns_code::BAR_2, 1, 2, cgns_code::BAR_2, 2, 5, cgns_code::BAR_2, 5, 6, cgns_code::BAR_2, 4, 1}},
                  {"top", cgns_code::BAR_2, 2, {6, 3, 3, 4}}};
    z.cells = 3;
    return z;
}

/// The face rings of polyhedron c of `list`, in order.
/// Faces as cycles from their smallest node, sorted: the same faces turned the same way compare equal.
std::vector<std::vector<NodeId>> cgns_cycles(std::vector<std::vector<NodeId>> faces) {
    for (auto& f : faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    std::sort(faces.begin(), faces.end());
    return faces;
}

/// The outward faces of cell c of any type (a fixed type's from
/// foam::outward_faces), each as a cycle from its smallest node, sorted.
std::vector<std::vector<NodeId>> cgns_cell_faces(const ElementList& list, std::size_t c) {
    std::vector<std::vector<NodeId>> faces;
    if (list.types[c] == CellType::polyhedron) {
        const auto [f0, f1] = list.faces_of(c);
        for (std::int64_t f = f0; f < f1; ++f) faces.emplace_back(list.face_nodes_of(f).begin(), list.face_nodes_of(f).end());
    } else {
        const auto nodes = list.nodes_of(c);
        const foam::FaceTable& t = foam::outward_faces(list.types[c]);
        for (int k = 0; k < t.count; ++k) {
            faces.emplace_back();
            for (int i = 0; i < t.size[k]; ++i) faces.back().push_back(nodes[static_cast<std::size_t>(t.node[k][i])]);
        }
    }
    return cgns_cycles(std::move(faces));
}

}  // namespace

// aflr3_to_cgns's file holds the Gmsh mesh it was made from (through
// sources/msh_to_ugrid.py): the same points bit for bit, the same cells in VTK
// order (positive volumes), the boundary faces of each surface id as a marker.
TEST(CgnsRead, Aflr3ToCgnsFileHoldsTheMeshItWasMadeFrom) {
    const Mesh source = cgns_source_mixed();
    CgnsSource info;
    const Mesh mesh = read_cgns(cgns_data("mixed.cgns"), &info);
    EXPECT_EQ(mesh.dim, 3);
    EXPECT_EQ(mesh.points, source.points);
    EXPECT_EQ(cgns_sorted_elements(mesh.cells), cgns_sorted_elements(source.cells));
    const std::vector<std::int8_t> o = cell_orientations(mesh);
    EXPECT_EQ(std::count(o.begin(), o.end(), 1), static_cast<std::ptrdiff_t>(mesh.cells.size()));
    // aflr3_to_cgns names its BCs "UserDefined <n>", one per section of
    // triangles or quadrilaterals of a surface id (sources/README.md).
    ASSERT_EQ(mesh.markers.size(), 5u);
    std::size_t elements = 0;
    for (const Marker& m : mesh.markers) {
        EXPECT_EQ(m.name.rfind("UserDefined ", 0), 0u) << m.name;
        elements += m.elements.size();
    }
    std::size_t source_elements = 0;
    for (const Marker& m : source.markers) source_elements += m.elements.size();
    EXPECT_EQ(elements, source_elements);
    ASSERT_EQ(info.zones.size(), 1u);
    EXPECT_EQ(info.zones[0].name, "Zone");
    EXPECT_EQ(info.num_points, mesh.num_points());
    EXPECT_EQ(info.zones[0].points.size(), mesh.num_points());
    EXPECT_EQ(info.zones[0].points[41], 41);
}

TEST(CgnsRead, TheAdfCopyReadsTheSame) {
    EXPECT_TRUE(read_cgns(cgns_data("mixed-adf.cgns")) == read_cgns(cgns_data("mixed.cgns")));
    EXPECT_TRUE(read_cgns(cgns_data("tet-adf.cgns")) == read_cgns(cgns_data("tet.cgns")));
}

TEST(CgnsRead, AStructuredZoneIsRefusedByName) {
    expect_cgns_error<FormatError>(cgns_data("cube-structured.cgns"),
                                   {"cube-structured.cgns", "zone 'Zone1' is structured", "unstructured zones only"});
}

// Two zones joined by vertex 1-to-1 connectivity share the points of their
// interface: the mesh is the original, points renumbered; without the
// connectivity their points stay apart.
TEST(CgnsRead, ZonesShareThePointsTheirOneToOneConnectivityJoins) {
    const Mesh source = cgns_source_mixed();
    std::vector<std::size_t> first, second;
    for (std::size_t c = 0; c < source.cells.size(); ++c) (c % 3 == 0 ? first : second).push_back(c);
    std::map<NodeId, cgns_size> in_a, in_b;
    TestZone a = cgns_zone_of(source, first, "A", in_a), b = cgns_zone_of(source, second, "B", in_b);
    TestJoin ab{"A", {}, {}}, ba{"B", {}, {}};
    for (const auto& [v, vb] : in_b)
        if (in_a.count(v)) {
            ab.points.push_back(vb);
            ab.donor_points.push_back(in_a[v]);
            ba.points.push_back(in_a[v]);
            ba.donor_points.push_back(vb);
        }
    ASSERT_GT(ab.points.size(), 10u);
    const auto dir = scratch_dir();
    write_test_cgns(dir / "apart.cgns", 3, {a, b});
    b.joins = {ab};
    a.joins = {ba};
    write_test_cgns(dir / "joined.cgns", 3, {a, b});

    Mesh expected = source;
    expected.cells = {};
    for (std::size_t c : first) expected.cells.push_back(source.cells.types[c], source.cells.nodes_of(c));
    for (std::size_t c : second) expected.cells.push_back(source.cells.types[c], source.cells.nodes_of(c));
    CgnsSource info;
    const Mesh joined = read_cgns(dir / "joined.cgns", &info);
    EXPECT_EQ(joined.num_points(), source.num_points());
    EXPECT_EQ(cgns_cell_corners(joined), cgns_cell_corners(expected));
    ASSERT_EQ(info.zones.size(), 2u);
    EXPECT_EQ(info.zones[1].name, "B");
    for (const auto& [v, vb] : in_b)  // zone B's vertex is the point of the same place
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(joined.points[3 * static_cast<std::size_t>(info.zones[1].points[static_cast<std::size_t>(vb - 1)]) + static_cast<std::size_t>(k)],
                      source.points[3 * static_cast<std::size_t>(v) + static_cast<std::size_t>(k)]);

    const Mesh apart = read_cgns(dir / "apart.cgns");
    EXPECT_EQ(apart.num_points(), in_a.size() + in_b.size());
    EXPECT_EQ(cgns_cell_corners(apart), cgns_cell_corners(expected));
}

// BCs on vertices take the faces whose nodes are all in them; BCs of one
// family are one marker of the family's name; a face section no BC refers to
// is a marker of its name; MIXED sections hold cells and faces.
TEST(CgnsRead, VertexBcsFamiliesAndUnreferencedSectionsAreMarkers) {
    TestZone z = cgns_square_zone();
    z.bcs = {{"lower", "wall", cgns_code::Vertex, false, {1, 2, 5}},
             {"right", "", cgns_code::EdgeCenter, true, {6, 6}},
             {"left", "wall", cgns_code::EdgeCenter, false, {7}}};
    const auto dir = scratch_dir();
    write_test_cgns(dir / "square.cgns", 2, {z});
    const Mesh mesh = read_cgns(dir / "square.cgns");
    EXPECT_EQ(mesh.dim, 2);
    EXPECT_EQ(mesh.points, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1}));
    ASSERT_EQ(mesh.cells.size(), 3u);
    EXPECT_EQ(mesh.cells.types[2], CellType::quadrilateral);
    ASSERT_EQ(mesh.markers.size(), 3u);
    EXPECT_EQ(mesh.markers[0].name, "wall");  // lower (vertices 1, 2, 5: two bars) and left
    EXPECT_EQ(mesh.markers[0].elements.nodes, (std::vector<NodeId>{0, 1, 1, 4, 3, 0}));
    EXPECT_EQ(mesh.markers[1].name, "right");
    EXPECT_EQ(mesh.markers[1].elements.nodes, (std::vector<NodeId>{4, 5}));
    EXPECT_EQ(mesh.markers[2].name, "top");  // no BC refers to it
    EXPECT_EQ(mesh.markers[2].elements.nodes, (std::vector<NodeId>{5, 2, 2, 3}));

    // 3D without face elements: a vertex BC takes the cells' boundary faces, pointing out.
    TestZone t = cgns_tet_zone();
    t.sections.pop_back();
    t.bcs = {{"slant", "", cgns_code::Vertex, false, {2, 3, 4}}, {"all", "", cgns_code::Vertex, true, {1, 4}}};
    write_test_cgns(dir / "tet.cgns", 3, {t});
    const Mesh tet = read_cgns(dir / "tet.cgns");
    ASSERT_EQ(tet.markers.size(), 2u);
    EXPECT_EQ(tet.markers[0].elements.nodes, (std::vector<NodeId>{1, 2, 3}));
    EXPECT_EQ(tet.markers[1].elements.size(), 4u);
}

TEST(CgnsRead, BadContentIsNamedByFileZoneSectionAndBc) {
    const auto dir = scratch_dir();
    TestZone z = cgns_tet_zone();
    z.sections[0].connectivity = {1, 2, 3, 5};
    write_test_cgns(dir / "node.cgns", 3, {z});
    expect_cgns_error<ParseError>(dir / "node.cgns", {"node.cgns", "node numbers from 1 to 4 in element 1 of section "
                                                                   "'Cells' of zone 'Zone'", "found '5'"});
    z = cgns_tet_zone();
    z.bcs = {{"wall", "", cgns_code::FaceCenter, false, {1}}};
    write_test_cgns(dir / "bc.cgns", 3, {z});
    expect_cgns_error<ParseError>(dir / "bc.cgns", {"bc.cgns", "face elements (of dimension 2) of zone 'Zone' in BC 'wall'",
                                                    "found '1'"});
    z = cgns_tet_zone();
    z.sections[1] = {"curved", cgns_code::TRI_6, 1, {1, 3, 2, 1, 2, 3}};
    write_test_cgns(dir / "order.cgns", 3, {z});
    expect_cgns_error<FormatError>(dir / "order.cgns", {"order.cgns", "section 'curved' of zone 'Zone' holds TRI_6"});
    z = cgns_tet_zone();
    z.joins = {{"Elsewhere", {1}, {1}}};
    write_test_cgns(dir / "donor.cgns", 3, {z});
    expect_cgns_error<ParseError>(dir / "donor.cgns", {"donor.cgns", "connectivity 1 of zone 'Zone'", "Elsewhere"});
    z = cgns_tet_zone();
    z.y[2] = std::nan("");
    write_test_cgns(dir / "nan.cgns", 3, {z});
    expect_cgns_error<ParseError>(dir / "nan.cgns", {"nan.cgns", "a finite CoordinateY of vertex 3 of zone 'Zone'", "found 'nan'"});
    expect_cgns_error<IoError>(dir / "missing.cgns", {"missing.cgns", "No such file"});
    write_text(dir / "text.cgns", "NDIME= 2\n");
    expect_cgns_error<IoError>(dir / "text.cgns", {"text.cgns", "cannot open as a CGNS file"});
}

// libcgns 3.4 reads a node's data through a pointer it never set when the
// node's data type is not one it knows (exactly MT, I4, I8, R4, R8, C1): the
// fuzzer's ADF file (a BC's GridLocation of type "c1") made it write into
// memory it had freed. The tree walk before cg_open refuses such a node by its path.
TEST(CgnsRead, ANodeOfADataTypeLibcgnsCannotReadIsRefusedByItsPath) {
    const auto adf = source_dir() / "tests" / "data" / "fuzz_regressions" / "cgns" / "adf-bc-gridlocation-type-c1.cgns";
    expect_cgns_error<IoError>(adf, {adf.string(), "it is damaged (/Base/Zone/ZoneBC/UserDefined 5/GridLocation: data of "
                                                   "type 'c1'; CGNS's types are MT, I4, I8, R4, R8 and C1)"});
    const auto dir = scratch_dir();
    TestZone z = cgns_tet_zone();
    z.bcs = {{"wall", "", cgns_code::FaceCenter, false, {2}}};
    write_test_cgns(dir / "b1.cgns", 3, {z});
    ASSERT_NO_THROW(read_cgns(dir / "b1.cgns"));
    set_cgns_node_data(dir / "b1.cgns", "/Base/Zone/ZoneBC/wall/GridLocation", "B1", "FaceCenter");
    expect_cgns_error<IoError>(dir / "b1.cgns", {"b1.cgns", "(/Base/Zone/ZoneBC/wall/GridLocation: data of type 'B1'"});
}

// ADF takes bytes 100 and 101 of its header (numeric format, pointer size)
// as they are and asserts, aborting the program, when one is 0 (the fuzzer's
// crash-994eedb...): anything but 'B' or 'L' is refused before libcgns opens the file.
TEST(CgnsRead, AnAdfHeaderOfAnotherNumericFormatIsRefused) {
    const auto dir = scratch_dir();
    const std::string bytes = slurp(cgns_data("tet-adf.cgns"));
    ASSERT_EQ(bytes.substr(100, 2), "LB");
    for (const auto& [at, value] : std::vector<std::pair<std::size_t, char>>{{100, '\0'}, {101, '\0'}, {100, 'C'}, {101, 'x'}}) {
        std::string damaged = bytes;
        damaged[at] = value;
        write_text(dir / "format.cgns", damaged);
        expect_cgns_error<IoError>(dir / "format.cgns", {"format.cgns", "its ADF header is damaged (its numeric format"});
    }
}

// The files written here are valid CGNS (when the CGNS tools are installed:
// scripts/install-deps.sh installs cgns-convert).
TEST(CgnsRead, TheTestWriterFilesPassCgnscheck) {
    if (run_command("command -v cgnscheck").exit_code != 0) GTEST_SKIP() << "cgnscheck not installed (Debian package cgns-convert)";
    const auto dir = scratch_dir();
    TestZone z = cgns_tet_zone();
    z.bcs = {{"base", "wall", cgns_code::FaceCenter, false, {2}}, {"tip", "", cgns_code::Vertex, false, {4}}};
    write_test_cgns(dir / "checked.cgns", 3, {z});
    // Two zones with 1-to-1 connectivity, MIXED sections of cells and faces in 2D.
    TestZone a = cgns_tet_zone(), b = cgns_tet_zone();
    a.name = "A";
    b.name = "B";
    b.z = {0, 0, 0, -1};
    b.sections[0].connectivity = {1, 3, 2, 4};
    b.joins = {{"A", {1, 2, 3}, {1, 2, 3}}};
    write_test_cgns(dir / "zones.cgns", 3, {a, b});
    TestZone square;
    square.x = {0, 1, 1, 0};
    square.y = {0, 0, 1, 1};
    square.sections = {{"All", cgns_code::MIXED, 3,
                        {cgns_code::TRI_3, 1, 2, 3, cgns_code::TRI_3, 1, 3, 4, cgns_code::BAR_2, 1, 2}}};
    square.cells = 2;
    square.bcs = {{"lower", "", cgns_code::EdgeCenter, false, {3}}};
    write_test_cgns(dir / "square.cgns", 2, {square});
    for (const char* name : {"checked.cgns", "zones.cgns", "square.cgns"}) {
        const CommandResult r = run_command("cgnscheck " + quoted(dir / name));
        EXPECT_EQ(r.exit_code, 0) << name << r.out << r.err;
        EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << name << "\n" << r.out;
        EXPECT_NO_THROW(read_cgns(dir / name)) << name;
    }
}

// Each marker's BC type is kept (CgnsSource::marker_types): a BC's own, or for
// FamilySpecified its family's FamilyBC_t; "" for a section no BC refers to.
TEST(CgnsRead, MarkersKeepTheirBcTypes) {
    TestZone z = cgns_square_zone();
    z.bcs = {{"lower", "", cgns_code::Vertex, false, {1, 2, 5}, cgns_code::BCSymmetryPlane},
             {"right", "", cgns_code::EdgeCenter, true, {6, 6}},
             {"left", "mirror", cgns_code::EdgeCenter, false, {7}, cgns_code::BCWall, cgns_code::BCSymmetryPlane}};
    const auto dir = scratch_dir();
    write_test_cgns(dir / "typed.cgns", 2, {z});
    CgnsSource info;
    const Mesh mesh = read_cgns(dir / "typed.cgns", &info);
    ASSERT_EQ(mesh.markers.size(), 4u);
    EXPECT_EQ(mesh.markers[2].name, "mirror");
    EXPECT_EQ(info.marker_types, (std::vector<std::string>{"BCSymmetryPlane", "BCWall", "BCSymmetryPlane", ""}));
}

// A file with neither BCs nor face sections: its cells' exterior faces are
// one marker, `exterior`, pointing out of the cells (so that it can be deformed).
TEST(CgnsRead, AFileWithoutBoundariesGetsItsExteriorFacesAsOneMarker) {
    TestZone z;
    // Two tetrahedra sharing the face 2-3-4: 6 exterior faces.
    z.x = {0, 1, 0, 0, 1};
    z.y = {0, 0, 1, 0, 1};
    z.z = {0, 0, 0, 1, 1};
    z.sections = {{"Cells", cgns_code::TETRA_4, 2, {1, 2, 3, 4, 2, 5, 3, 4}}};
    const auto dir = scratch_dir();
    write_test_cgns(dir / "bare.cgns", 3, {z});
    CgnsSource info;
    const Mesh mesh = read_cgns(dir / "bare.cgns", &info);
    ASSERT_EQ(mesh.markers.size(), 1u);
    EXPECT_EQ(mesh.markers[0].name, "exterior");
    EXPECT_TRUE(info.exterior_marker);
    ASSERT_EQ(mesh.markers[0].elements.size(), 6u);
    // Each face points out: away from its cell's fourth node.
    for (std::size_t f = 0; f < 6; ++f) {
        const auto n = mesh.markers[0].elements.nodes_of(f);
        std::array<double, 3> a{}, b{}, centre{};
        for (int k = 0; k < 3; ++k) {
            a[k] = mesh.points[3 * n[1] + k] - mesh.points[3 * n[0] + k];
            b[k] = mesh.points[3 * n[2] + k] - mesh.points[3 * n[0] + k];
        }
        const std::array<double, 3> normal{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        for (int k = 0; k < 3; ++k) centre[k] = (mesh.points[3 * n[0] + k] + mesh.points[3 * n[1] + k] + mesh.points[3 * n[2] + k]) / 3;
        // The mesh's centroid (0.4, 0.4, 0.4) is inside: the normal points away from it.
        double out = 0;
        for (int k = 0; k < 3; ++k) out += normal[k] * (centre[k] - 0.4);
        EXPECT_GT(out, 0) << f;
    }
}

// NGON_n faces and NFACE_n cells (CGNS SIDS 7.3): each cell a polyhedron
// whose faces point out of it, a face named by a negative number turned round
// (from its first node); in whichever order the two sections come. A BC of
// NGON_n element numbers takes those faces as written; a vertex BC takes the
// cells' boundary faces (pointing out), never an inner face.
TEST(CgnsRead, NfaceCellsArePolyhedraTheirFacesTurnedOut) {
    const auto dir = scratch_dir();
    for (const bool cells_first : {false, true}) {
        TestZone z = split_cube_test_zone(cells_first);
        const cgns_size f = cells_first ? 2 : 0;
        z.bcs = {{"bottom", "", cgns_code::FaceCenter, false, {f + 1, f + 2}},
                 {"top", "", cgns_code::Vertex, false, {5, 6, 7, 8}},
                 {"cut", "", cgns_code::Vertex, false, {1, 3, 5, 7}}};
        write_test_cgns(dir / "cube.cgns", 3, {z});
        const Mesh mesh = read_cgns(dir / "cube.cgns");
        EXPECT_EQ(mesh.points, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}));
        ASSERT_EQ(mesh.cells.size(), 2u) << cells_first;
        // Prisms by their faces (as OpenFOAM's cells are read).
        EXPECT_EQ(mesh.cells.types, (std::vector<CellType>{CellType::prism, CellType::prism}));
        // A: faces -1, 3, 5, 6, -9; B: -2, 4, 7, 8, 9 (0-based nodes).
        EXPECT_EQ(cgns_cell_faces(mesh.cells, 0),
                  cgns_cycles({{0, 2, 1}, {4, 5, 6}, {0, 1, 5, 4}, {1, 2, 6, 5}, {0, 4, 6, 2}}));
        EXPECT_EQ(cgns_cell_faces(mesh.cells, 1),
                  cgns_cycles({{0, 3, 2}, {4, 6, 7}, {2, 3, 7, 6}, {3, 0, 4, 7}, {0, 2, 6, 4}}));
        for (std::size_t c = 0; c < 2; ++c) {
            EXPECT_EQ(element_orientation(mesh.cells, c, 3, mesh.points), 1) << c;
            EXPECT_GT(element_shape_quality(mesh.cells, c, 3, mesh.points), 0.5) << c;
        }
        ASSERT_EQ(mesh.markers.size(), 3u);  // no marker of the section "Faces": the cells' faces
        EXPECT_EQ(mesh.markers[0].name, "bottom");
        EXPECT_EQ(mesh.markers[0].elements.types, (std::vector<CellType>{CellType::triangle, CellType::triangle}));
        EXPECT_EQ(mesh.markers[0].elements.nodes, (std::vector<NodeId>{0, 1, 2, 0, 2, 3}));  // as written
        EXPECT_EQ(mesh.markers[1].name, "top");
        EXPECT_EQ(mesh.markers[1].elements.nodes, (std::vector<NodeId>{4, 5, 6, 4, 6, 7}));
        EXPECT_EQ(mesh.markers[2].name, "cut");  // the inner face x = y is no boundary face
        EXPECT_TRUE(mesh.markers[2].elements.empty());
    }
    // Without BCs: the cells' exterior faces, pointing out, are the marker `exterior`.
    write_test_cgns(dir / "bare.cgns", 3, {split_cube_test_zone(false)});
    const Mesh bare = read_cgns(dir / "bare.cgns");
    ASSERT_EQ(bare.markers.size(), 1u);
    EXPECT_EQ(bare.markers[0].name, "exterior");
    std::vector<std::vector<NodeId>> exterior;
    for (std::size_t e = 0; e < bare.markers[0].elements.size(); ++e)
        exterior.emplace_back(bare.markers[0].elements.nodes_of(e).begin(), bare.markers[0].elements.nodes_of(e).end());
    EXPECT_EQ(cgns_cycles(exterior), cgns_cycles({{0, 2, 1}, {4, 5, 6}, {0, 1, 5, 4}, {1, 2, 6, 5}, {0, 3, 2}, {4, 6, 7},
                                                  {2, 3, 7, 6}, {3, 0, 4, 7}}));
}

// A pyramid-shaped NFACE_n cell, three of its five faces written turned into
// it: with the right signs its faces are the pyramid's outward faces (those of
// the VTK-ordered pyramid 0-1-2-3-4). A cell whose signs disagree (every face
// named positive, as some writers do) is turned out by its shape; one whose
// faces all point in, consistently, is kept so: an inverted cell (orientation -1).
TEST(CgnsRead, NegativeFaceNumbersTurnTheFaceRound) {
    const auto dir = scratch_dir();
    const std::vector<std::vector<NodeId>> outward{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    for (const auto& signs : {std::vector<int>{-1, 1, -1, 1, -1}, std::vector<int>{1, 1, 1, 1, 1}}) {
        write_test_cgns(dir / "pyramid.cgns", 3, {pyramid_test_zone(signs)});
        const Mesh mesh = read_cgns(dir / "pyramid.cgns");
        ASSERT_EQ(mesh.cells.size(), 1u);
        EXPECT_EQ(mesh.cells.types[0], CellType::pyramid);
        EXPECT_EQ(cgns_cell_faces(mesh.cells, 0), cgns_cycles(outward)) << signs[0];
        EXPECT_EQ(element_orientation(mesh.cells, 0, 3, mesh.points), 1);
        EXPECT_GT(element_shape_quality(mesh.cells, 0, 3, mesh.points), 0);
    }
    write_test_cgns(dir / "inverted.cgns", 3, {pyramid_test_zone({1, -1, 1, -1, 1})});
    const Mesh inverted = read_cgns(dir / "inverted.cgns");
    EXPECT_EQ(inverted.cells.types[0], CellType::pyramid);  // a pyramid turned inside out
    EXPECT_EQ(cgns_cell_faces(inverted.cells, 0), cgns_cycles({{0, 1, 2, 3}, {0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}}));
    EXPECT_EQ(element_orientation(inverted.cells, 0, 3, inverted.points), -1);
    EXPECT_LE(element_shape_quality(inverted.cells, 0, 3, inverted.points), 0);
}

// A 2D zone's NGON_n elements are its cells: polygons, triangles and
// quadrilaterals by their node count; its BAR_2 edges are faces as before.
TEST(CgnsRead, A2dZoneNgonElementsArePolygonCells) {
    TestZone z;
    z.x = {0, 1, 2, 2, 1, 0, 1.2, 1};
    z.y = {0, 0, 0, 1, 1, 1, 0.5, -1};
    z.sections = {{"Cells", cgns_code::NGON_n, 3, {5, 1, 2, 7, 5, 6, 5, 2, 3, 4, 5, 7, 3, 1, 8, 2}},
                  {"left", cgns_code::BAR_2, 1, {6, 1}}};
    z.cells = 3;
    const auto dir = scratch_dir();
    write_test_cgns(dir / "polygons.cgns", 2, {z});
    const Mesh mesh = read_cgns(dir / "polygons.cgns");
    EXPECT_EQ(mesh.dim, 2);
    EXPECT_EQ(mesh.cells.types, (std::vector<CellType>{CellType::polygon, CellType::polygon, CellType::triangle}));
    EXPECT_EQ(mesh.cells.nodes, (std::vector<NodeId>{0, 1, 6, 4, 5, 1, 2, 3, 4, 6, 0, 7, 1}));
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(element_orientation(mesh.cells, c, 2, mesh.points), 1) << c;
    ASSERT_EQ(mesh.markers.size(), 1u);
    EXPECT_EQ(mesh.markers[0].name, "left");
    EXPECT_EQ(mesh.markers[0].elements.nodes, (std::vector<NodeId>{5, 0}));
}

TEST(CgnsRead, PolyhedralFilesPassCgnscheck) {
    if (run_command("command -v cgnscheck").exit_code != 0) GTEST_SKIP() << "cgnscheck not installed (Debian package cgns-convert)";
    const auto dir = scratch_dir();
    TestZone z = split_cube_test_zone(false);
    z.bcs = {{"bottom", "", cgns_code::FaceCenter, false, {1, 2}}};
    write_test_cgns(dir / "cube.cgns", 3, {z});
    const CommandResult r = run_command("cgnscheck " + quoted(dir / "cube.cgns"));
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << r.out;
}
